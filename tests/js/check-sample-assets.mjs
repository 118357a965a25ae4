// Public glTF sample assets as they arrive (sample-asset-shapes.mjs: the materials of Khronos's
// FlightHelmet, CompareMetallic, ClearCoatCarPaint and IridescenceMetallicSpheres, placeholder
// buffers and images beside them)
// through matc as a pipeline runs it:
//   - `matc gltf` into another folder: exit 0, every metal given MATC_materials_fresnel, the files
//     the asset names copied beside the output byte for byte, and the Khronos glTF-Validator reports
//     the output exactly as the input plus its information that it does not know the extension;
//   - `matc import` and `matc -o` (compile): exit 0, one material file and one compile per metal,
//     the notes for what is not carried (textured metalness, transmission, a coat over partial
//     metalness) printed, nothing refused;
//   - the npm package reads each asset (with its buffers given) to the same metals;
//   - the Python module (when PYTHON and PYTHON_DIR are given: the interpreter the build's module
//     is for, the build's python/) writes each asset as `matc gltf` does (compile_gltf: the same
//     bytes) and evaluates a metal with `metalness=`.
//   node check-sample-assets.mjs MATC NPM_DIR [PYTHON PYTHON_DIR]
import { spawnSync } from "node:child_process";
import { mkdirSync, mkdtempSync, readFileSync, readdirSync, rmSync } from "node:fs";
import { tmpdir } from "node:os";
import { dirname, join } from "node:path";
import validator from "gltf-validator";
import { check, finish } from "./report.mjs";
import { kSampleAssetShapes, writeSampleAsset } from "./sample-asset-shapes.mjs";

const [matc, npmDir, python, pythonDir] = process.argv.slice(2);

// Python's compile_gltf of `asset` (its bytes, base64) and the metals it names, and evaluate() of
// `materialFile` at metalness 0.5 (F_metal_rough at mu 0.5; a coated metal's base and coat lobes),
// as JSON on standard output.
function pythonRun(asset, materialFile) {
  const script = `import base64, json, sys, matc
written = matc.compile_gltf(sys.argv[1])
mix = matc.evaluate(sys.argv[2], mu=[0.5], reference=False, metalness=0.5)
print(json.dumps({"bytes": base64.b64encode(written.bytes).decode(), "metals": len(written.materials),
                  "mix": mix["F_metal_rough"][0], "dielectric": mix["F_dielectric"][0],
                  "base": mix.get("F_base", mix["F"])[0], "coat": mix.get("F_coat", [0])[0]}))`;
  // The written asset comes back as base64 on standard output: IridescenceMetallicSpheres' 294
  // filmed metals carry their tables (5.8 MB, 7.7 MB as base64), past spawnSync's default buffer.
  const result = spawnSync(python, ["-c", script, asset, materialFile],
                           { encoding: "utf8", env: { ...process.env, PYTHONPATH: pythonDir },
                             maxBuffer: 256 * 1024 * 1024 });
  if (result.status !== 0) return { error: result.stderr };
  return JSON.parse(result.stdout);
}
const kExtension = "MATC_materials_fresnel";

const matcRun = (args) => spawnSync(matc, args, { encoding: "utf8" });

async function validated(path) {
  return validator.validateBytes(new Uint8Array(readFileSync(path)), {
    uri: path, maxIssues: 1000,
    externalResourceFunction: async (uri) => new Uint8Array(readFileSync(join(dirname(path), decodeURIComponent(uri)))),
  });
}
const messages = (report) => report.issues.messages
  .map((m) => `${m.code} ${(m.pointer ?? "").replace(/^\/extensionsUsed\/\d+$/, "/extensionsUsed")}`).sort();

const { createMatc } = await import(join(npmDir, "index.mjs"));
const wasm = await createMatc();
const dir = mkdtempSync(join(tmpdir(), "matc-sample-assets-"));
let metals = 0, pythonAssets = 0;
try {
  for (const shape of kSampleAssetShapes) {
    const folder = join(dir, shape.name);
    mkdirSync(folder);
    const asset = writeSampleAsset(shape, folder);
    const output = join(dir, "out", shape.name, `${shape.name}.gltf`);
    const written = matcRun(["gltf", asset, "-o", output]);
    check(written.status === 0, `${shape.name}: matc gltf: exit ${written.status}: ${written.stderr}`);
    if (written.status !== 0) continue;
    const json = JSON.parse(readFileSync(output, "utf8"));
    const carrying = json.materials.filter((material) => material.extensions?.[kExtension]).length;
    check(carrying === shape.metals, `${shape.name}: ${carrying} metals carry ${kExtension}, not ${shape.metals}`);
    metals += carrying;
    for (const file of [...shape.buffers.map(([uri]) => uri), ...shape.images]) {
      check(Buffer.compare(readFileSync(join(folder, file)), readFileSync(join(dirname(output), file))) === 0,
            `${shape.name}: ${file} is not copied beside the output byte for byte`);
    }
    const [before, after] = [await validated(asset), await validated(output)];
    const added = messages(after).filter((m) => !messages(before).includes(m));
    check(after.issues.numErrors === before.issues.numErrors && added.length === 1 &&
          added[0].startsWith("UNSUPPORTED_EXTENSION"),
          `${shape.name}: the validator's findings beyond the input's: ${added.join("; ")} ` +
          `(errors ${before.issues.numErrors} -> ${after.issues.numErrors})`);
    // The importer and the compile, as a pipeline runs them.
    const imported = matcRun(["import", "-o", join(dir, "materials", shape.name), asset]);
    check(imported.status === 0 && readdirSync(join(dir, "materials", shape.name)).length === shape.metals,
          `${shape.name}: matc import: exit ${imported.status}: ${imported.stderr}`);
    const compiled = matcRun(["-q", "-o", join(dir, "build", shape.name), "--emit", "json", asset]);
    check(compiled.status === 0, `${shape.name}: matc -o: exit ${compiled.status}: ${compiled.stderr}`);
    // The npm package, the asset's buffers given as the files beside it.
    const files = Object.fromEntries(shape.buffers.map(([uri]) => [uri, new Uint8Array(readFileSync(join(folder, uri)))]));
    const parsed = wasm.parseMaterials(readFileSync(asset, "utf8"), `${shape.name}.gltf`, { files });
    check(parsed.length === shape.metals, `${shape.name}: the npm package reads ${parsed.length} metals`);
    if (pythonDir) {
      const materialFile = join(dir, "materials", shape.name, readdirSync(join(dir, "materials", shape.name))[0]);
      const python = pythonRun(asset, materialFile);
      check(!python.error, `${shape.name}: Python: ${python.error}`);
      if (python.error) continue;
      check(python.metals === shape.metals, `${shape.name}: Python's compile_gltf names ${python.metals} metals`);
      check(Buffer.compare(Buffer.from(python.bytes, "base64"), readFileSync(output)) === 0,
            `${shape.name}: Python's compile_gltf bytes differ from matc gltf's`);
      // Under a coat (ClearCoatCarPaint's paint), the coat lobe over the mix and the dielectric under
      // the coat's transmission.
      const { coat } = python;
      const mixed = python.mix.every((value, c) =>
        Math.abs(value - (coat + 0.5 * (1 - coat) * python.dielectric[c] + 0.5 * python.base[c])) <= 1e-15);
      check(mixed, `${shape.name}: Python's metalness=0.5 is not the mix: ${python.mix}`);
      pythonAssets += 1;
    }
  }
  check(metals === 351, `${metals} metals written`);
  console.log(`${kSampleAssetShapes.length} public sample assets' materials (${kSampleAssetShapes.map((s) => s.name).join(", ")}): ` +
              `${metals} metals through matc gltf (copied beside an output in another folder, glTF-Validator findings ` +
              `unchanged but for the vendor extension), matc import, matc -o, the npm package` +
              `${pythonDir ? ` and Python (${pythonAssets} assets: compile_gltf byte for byte, evaluate with metalness)` : ""}; ` +
              "nothing refused");
} finally {
  rmSync(dir, { recursive: true, force: true });
}
finish();
