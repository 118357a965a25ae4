// Stages the npm package: the sources here, the WebAssembly build's module and binary, and the
// shared tables written by the native matc (the same files `matc -o` writes).
//   node stage.mjs WASM_BUILD_DIR OUT_DIR MATC
import { execFileSync } from "node:child_process";
import fs from "node:fs";
import path from "node:path";
import { fileURLToPath } from "node:url";

const [wasmDir, outDir, matc] = process.argv.slice(2);
if (!wasmDir || !outDir || !matc) {
  console.error("usage: node stage.mjs WASM_BUILD_DIR OUT_DIR MATC");
  process.exit(2);
}
const here = path.dirname(fileURLToPath(import.meta.url));
const root = path.join(here, "..", "..");
const project = fs.readFileSync(path.join(root, "CMakeLists.txt"), "utf8");
const version = /^project\(matc VERSION (\d+\.\d+\.\d+)/m.exec(project)?.[1];
const manifest = JSON.parse(fs.readFileSync(path.join(here, "package.json"), "utf8"));
if (manifest.version !== version) {
  console.error(`js/package/package.json: version ${manifest.version}, but the project is ${version}`);
  process.exit(1);
}

// The engine integrations read builds of this version (matc-build.mjs's kMatcVersion).
const integrationVersion = /kMatcVersion = "([^"]+)"/.exec(fs.readFileSync(path.join(here, "matc-build.mjs"), "utf8"))?.[1];
if (integrationVersion !== version) {
  console.error(`js/package/matc-build.mjs: kMatcVersion ${integrationVersion}, but the project is ${version}`);
  process.exit(1);
}

fs.rmSync(outDir, { recursive: true, force: true });
fs.mkdirSync(path.join(outDir, "tables"), { recursive: true });
fs.copyFileSync(path.join(here, "package.json"), path.join(outDir, "package.json"));
fs.copyFileSync(path.join(here, "index.d.ts"), path.join(outDir, "index.d.ts"));
fs.copyFileSync(path.join(here, "README.md"), path.join(outDir, "README.md"));
fs.writeFileSync(path.join(outDir, "index.mjs"),
                 fs.readFileSync(path.join(here, "index.mjs"), "utf8").replaceAll("@MATC_VERSION@", version));
for (const file of ["matc.mjs", "matc.wasm"]) fs.copyFileSync(path.join(wasmDir, file), path.join(outDir, file));
// The engine integrations (one source: the tests run these files).
for (const file of ["matc-build.mjs", "tables.mjs"]) fs.copyFileSync(path.join(here, file), path.join(outDir, file));
for (const [folder, files] of [["three", ["matc-three.mjs", "matc-three-webgpu.mjs", "matc-gltf.mjs", "textures.mjs", "README.md"]],
                               ["babylon", ["matc-babylon.mjs", "matc-gltf.mjs", "README.md"]],
                               ["lookdev", ["index.html", "lookdev.css", "lookdev.mjs", "lookdev-plot.mjs",
                                            "lookdev-state.mjs", "lookdev-view.mjs", "README.md"]]]) {
  fs.mkdirSync(path.join(outDir, folder));
  for (const file of files) fs.copyFileSync(path.join(here, folder, file), path.join(outDir, folder, file));
}

// The tables of the default build, as `matc` writes them (KTX2 and raw, each with its .json).
const tables = path.join(outDir, "tables");
for (const format of ["ktx2", "raw"]) {
  execFileSync(matc, ["-q", "--shared-only", "--emit", "lut,coefficient-table,ltc", "--lut", format, "-o", tables],
               { stdio: "inherit" });
}
for (const file of fs.readdirSync(tables)) {
  if (!/^matc_(lut|coefficient_table|ltc)\.(ktx2|bin)(\.json)?$/.test(file)) {
    console.error(`stage.mjs: unexpected table file ${file}`);
    process.exit(1);
  }
}
