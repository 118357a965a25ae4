// glTF assets as artists make them, built with glTF-Transform (npm @gltf-transform/core and
// extensions), read by matc (docs/gltf.md):
//   - car.glb: a car-paint material (a metallic base under KHR_materials_clearcoat, a base-colour
//     texture, normals and texture coordinates on its mesh), a chrome trim, a rubber tyre;
//   - trim.gltf (JSON, external .bin and .png beside it): a chrome whose specular colour is its F82
//     edge colour (EXT_materials_specular_edge_color inside KHR_materials_specular) and a
//     lacquered copper with KHR_materials_clearcoat_ior, both drafts glTF-Transform does not know,
//     written into its JSON as an exporter would.
// Checks: `matc import` writes each metal's material file with the asset's values (coat weight,
// roughness and index; F0; the edge colour) and notes what it does not carry (the texture, the
// tyre); `matc eval`'s exact curve is the glTF definition of each metal (Schlick's from F0; the
// F82-tint curve with the edge colour) and its F that curve within the compile's accuracy;
// `matc -o` compiles both assets; the npm package's compiler imports the same material files from
// the same bytes (the .gltf's buffer given in memory), and its compileGltf writes the .glb back as `matc gltf` does (the same bytes but
// for the last digits of the coefficients, where WebAssembly's math differs).
//   node check-gltf-assets.mjs MATC NPM_DIR
import { spawnSync } from "node:child_process";
import { mkdtempSync, readFileSync, rmSync, writeFileSync } from "node:fs";
import { tmpdir } from "node:os";
import { join, resolve } from "node:path";
import { carAsset, trimAsset } from "./gltf-assets.mjs";
import { check, finish } from "./report.mjs";
import { run } from "./shader-cases.mjs";

const [matc, npmDir] = process.argv.slice(2);

const schlick = (mu, f0) => f0 + (1 - f0) * (1 - mu) ** 5;
// Hoffman's F82-tint: Schlick's curve less a mu (1 - mu)^6, a so that F(1/7) = tint x Schlick(1/7).
function f82Tint(mu, f0, tint) {
  const bar = 1 / 7;
  const a = (schlick(bar, f0) * (1 - tint)) / (bar * (1 - bar) ** 6);
  return schlick(mu, f0) - a * mu * (1 - mu) ** 6;
}

const kCosines = Array.from({ length: 21 }, (_, i) => i / 20);

// `matc eval` of one material of an asset: its exact curve equals `definition` (the glTF
// metal's); its F at default options (the build's) is that curve within the compile's own accuracy
// (`accuracy`: the largest error per channel in the build's <name>.json), and within 1e-6 for a
// bare metal, which the default gives the f82 basis: it holds Schlick and F82-tint curves exactly
// (up to the float32 its coefficients are evaluated in). `powers`: the error with --basis powers.
function checkCurves(asset, material, definition, accuracy) {
  const evaluate = (basis) => JSON.parse(run(matc, ["eval", asset, "--material", material,
                                                    ...(basis ? ["--basis", basis] : []), "--mu", kCosines.join(",")]));
  const byDefault = evaluate(null), forced = evaluate("powers");
  let exact = 0, fitted = 0, powers = 0;
  kCosines.forEach((mu, i) => {
    for (let c = 0; c < 3; ++c) {
      const expected = definition(mu, c);
      exact = Math.max(exact, Math.abs(byDefault.F_exact[i][c] - expected));
      const error = Math.abs(byDefault.F[i][c] - expected);
      check(error <= accuracy[c] + 1e-12, `${material}: F at mu ${mu} is ${error} from the glTF definition, ` +
                                          `beyond the compile's accuracy ${accuracy[c]}`);
      fitted = Math.max(fitted, error);
      powers = Math.max(powers, Math.abs(forced.F[i][c] - expected));
    }
  });
  check(exact < 1e-12, `${material}: matc's exact curve is ${exact} from the glTF definition`);
  check(fitted < 1e-6, `${material}: at default options F is ${fitted} from the glTF definition`);
  return { exact, fitted, powers };
}

const dir = mkdtempSync(join(tmpdir(), "matc-gltf-assets-"));
try {
  const car = join(dir, "car.glb");
  await carAsset(car);
  await trimAsset(dir);
  const trim = join(dir, "trim.gltf");

  // matc import: the material files, and the notes.
  const out = join(dir, "imported");
  const importRun = spawnSync(matc, ["import", "-o", out, car, trim], { encoding: "utf8" });
  check(importRun.status === 0, `matc import: exit ${importRun.status}\n${importRun.stderr}`);
  const notes = importRun.stderr;
  const imported = (name) => JSON.parse(readFileSync(join(out, `${name}.json`), "utf8"));
  const paint = imported("Car_Paint");
  check(JSON.stringify(paint.f82_tint) === JSON.stringify({ f0: [0.55, 0.06, 0.05], tint: [1, 1, 1] }),
        `Car_Paint: ${JSON.stringify(paint.f82_tint)}`);
  check(paint.coat?.weight === 1 && paint.coat?.ior === 1.5 && paint.coat?.roughness === 0.03,
        `Car_Paint's coat: ${JSON.stringify(paint.coat)}`);
  const copper = imported("LacqueredCopper");
  check(copper.coat?.weight === 0.8 && copper.coat?.ior === 1.6, `LacqueredCopper's coat: ${JSON.stringify(copper.coat)}`);
  const edge = imported("EdgeChrome");
  check(JSON.stringify(edge.f82_tint.tint) === JSON.stringify([0.65, 0.68, 0.74]),
        `EdgeChrome's tint: ${JSON.stringify(edge.f82_tint)}`);
  for (const phrase of ['materials[0] "Car Paint": not carried: baseColorTexture',
                        'materials[2] "Tyre": not imported: not a metal']) {
    check(notes.includes(phrase), `matc import's notes lack ${phrase}:\n${notes}`);
  }

  // The curves: the glTF definition of each metal.
  const f0Chrome = [0.55, 0.556, 0.554];
  const tint = [0.65, 0.68, 0.74];
  // Both assets compile; then the curves against the glTF definition of each metal.
  run(matc, ["-q", "-o", join(dir, "build"), "--emit", "glsl,json", car, trim]);
  for (const name of ["Car_Paint", "Chrome", "EdgeChrome", "LacqueredCopper"]) {
    check(readFileSync(join(dir, "build", `${name}.glsl`), "utf8").includes(`matc_fresnel_${name}`), `${name}.glsl`);
  }
  const accuracy = (name) =>
    JSON.parse(readFileSync(join(dir, "build", `${name}.json`), "utf8")).accuracy.decomposition.max;
  const chromeCurves = checkCurves(car, "Chrome", (mu, c) => schlick(mu, f0Chrome[c]), accuracy("Chrome"));
  const edgeCurves = checkCurves(trim, "EdgeChrome", (mu, c) => f82Tint(mu, f0Chrome[c], tint[c]),
                                 accuracy("EdgeChrome"));

  // The npm package's compiler: the same material files from the same bytes (a .gltf's buffer
  // given to it in memory, as it has no file system).
  const { createMatc } = await import(resolve(npmDir, "index.mjs"));
  const wasm = await createMatc();
  const materials = [
    ...wasm.parseMaterials(new Uint8Array(readFileSync(car)), "car.glb"),
    ...wasm.parseMaterials(readFileSync(trim), "trim.gltf", { files: { "trim.bin": readFileSync(join(dir, "trim.bin")) } }),
  ];
  check(materials.map((m) => m.name).join() === "Car_Paint,Chrome,EdgeChrome,LacqueredCopper",
        `the package imports ${materials.map((m) => m.name)}`);
  for (const material of materials) {
    check(material.json === readFileSync(join(out, `${material.name}.json`), "utf8"),
          `${material.name}: the package's material file differs from matc import's`);
  }
  let refused = "";
  try {
    wasm.parseMaterials(readFileSync(trim), "trim.gltf");
  } catch (error) {
    refused = error.message;
  }
  check(/cannot read buffer 'trim.bin'/.test(refused), `a .gltf without its buffer given: ${refused}`);
  // compileGltf against `matc gltf`: every byte outside the extension's numbers, and the numbers
  // within 1e-9.
  const written = wasm.compileGltf(new Uint8Array(readFileSync(car)), "car.glb");
  check(written.materials.map((m) => `${m.name}:${m.coat ? "coated" : "bare"}`).join() === "Car_Paint:coated,Chrome:bare",
        `compileGltf's metals: ${written.materials.map((m) => m.name)}`);
  run(matc, ["gltf", "-q", car, "-o", join(dir, "car_matc.glb")]);
  const native = readFileSync(join(dir, "car_matc.glb"));
  const numbers = /-?\d+\.?\d*(?:[eE][-+]?\d+)?/g;
  const [ours, theirs] = [Buffer.from(written.bytes).toString("latin1"), native.toString("latin1")];
  const jsonEnd = (bytes) => 20 + bytes.readUInt32LE(12);
  check(Buffer.compare(Buffer.from(written.bytes).subarray(jsonEnd(Buffer.from(written.bytes))),
                       native.subarray(jsonEnd(native))) === 0, "compileGltf: the BIN chunk differs from matc gltf's");
  const [ourJson, theirJson] = [ours.slice(20, jsonEnd(Buffer.from(written.bytes))), theirs.slice(20, jsonEnd(native))];
  check(ourJson.replace(numbers, "#").trimEnd() === theirJson.replace(numbers, "#").trimEnd(),
        "compileGltf's JSON differs from matc gltf's beyond its numbers");
  const [ourNumbers, theirNumbers] = [ourJson.match(numbers).map(Number), theirJson.match(numbers).map(Number)];
  const gltfDifference = Math.max(...ourNumbers.map((value, i) => Math.abs(value - theirNumbers[i])));
  check(ourNumbers.length === theirNumbers.length && gltfDifference <= 1e-9,
        `compileGltf's numbers differ from matc gltf's by ${gltfDifference}`);
  console.log(`glTF assets built with glTF-Transform: 4 metals imported (2 coated, 1 edge-coloured), ` +
              `notes for the texture and the non-metal; exact curves equal the glTF definitions ` +
              `(${Math.max(chromeCurves.exact, edgeCurves.exact).toExponential(1)}), F within ` +
              `${Math.max(chromeCurves.fitted, edgeCurves.fitted).toExponential(1)} at default options (the f82 ` +
              `basis), ${chromeCurves.powers.toFixed(4)} (Schlick's chrome) and ${edgeCurves.powers.toFixed(4)} ` +
              `(the edge-coloured one) with --basis powers; the npm package ` +
              `imports both assets' material files byte for byte (the .gltf's buffer given in memory), and its ` +
              `compileGltf writes what matc gltf ` +
              `writes (numbers within ${gltfDifference.toExponential(1)})`);
} finally {
  rmSync(dir, { recursive: true, force: true });
}
finish();
