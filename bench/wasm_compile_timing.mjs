// The WebAssembly side of bench/wasm-compile.sh: the same passes as matc_api_compile_timing with
// the npm package's instance; prints "<parse+compile ms> <texts ms> <bytes>".
//   node wasm_compile_timing.mjs PACKAGE_DIR MATERIALS.jsonl RUNS
import fs from "node:fs";
import path from "node:path";

const [packageDir, materialsFile, runs] = process.argv.slice(2);
const { createMatc } = await import(path.resolve(packageDir, "index.mjs"));
const matc = await createMatc();
const inputs = fs.readFileSync(materialsFile, "utf8").trim().split("\n").map((line) => JSON.parse(line));
const texts = matc.textOutputs();
let bestCompile = Infinity, bestTexts = Infinity, bytes = 0;
for (let run = 0; run < Number(runs); ++run) {
  const compiled = [];
  const start = performance.now();
  for (const { text, path: name } of inputs) {
    for (const material of matc.parseMaterials(text, name)) compiled.push(matc.compile(material));
  }
  const compiledAt = performance.now();
  for (const material of compiled) {
    for (const language of ["glsl", "hlsl", "wgsl"]) bytes += texts.materialSource(language, material).length;
    bytes += texts.materialJson(material).length;
  }
  const done = performance.now();
  bestCompile = Math.min(bestCompile, compiledAt - start);
  bestTexts = Math.min(bestTexts, done - compiledAt);
  for (const material of compiled) { material.material.dispose(); material.dispose(); }
}
console.log(`${bestCompile} ${bestTexts} ${bytes / Number(runs)}`);
