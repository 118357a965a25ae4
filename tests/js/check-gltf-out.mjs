// glTF out (docs/gltf.md): `matc gltf` writes glTF-Transform-built assets back with each metal's
// compiled coefficients in MATC_materials_fresnel, checked by independent readers:
//   - the Khronos glTF-Validator (npm gltf-validator) reports no error, and exactly the input's
//     messages plus one: that it does not know the vendor extension (information, not a warning);
//   - every other byte is carried: a GLB's BIN chunk byte for byte; the JSON, with the extension
//     and its extensionsUsed entry taken out, deep-equals the input's (a .gltf's too);
//   - glTF-Transform reads the output: the same materials, factors, texture bytes and geometry;
//   - each extension object passes docs/gltf/MATC_materials_fresnel.schema.json (Ajv), and its
//     coefficients (and coat) equal those `matc -o` writes into <name>.json for the same asset;
//   - a second run over the output gives the same bytes; a .gltf written into another folder has
//     the files it names copied beside it (validated there); an asset without a metal is written
//     unchanged (exit 0); outputs that would overwrite the input or change the container are
//     refused, nothing written.
//   node check-gltf-out.mjs MATC SCHEMA
import { spawnSync } from "node:child_process";
import { existsSync, mkdirSync, mkdtempSync, readFileSync, readdirSync, rmSync, writeFileSync } from "node:fs";
import { tmpdir } from "node:os";
import { dirname, join } from "node:path";
import { Logger, NodeIO } from "@gltf-transform/core";
import { KHRONOS_EXTENSIONS } from "@gltf-transform/extensions";
import Ajv from "ajv";
import validator from "gltf-validator";
import { carAsset, trimAsset } from "./gltf-assets.mjs";
import { check, finish } from "./report.mjs";
import { run } from "./shader-cases.mjs";

const [matc, schemaPath] = process.argv.slice(2);
const kExtension = "MATC_materials_fresnel";
const validateExtension = new Ajv({ allErrors: true, strict: true }).compile(JSON.parse(readFileSync(schemaPath, "utf8")));

// The GLB's JSON (parsed) and the bytes after its JSON chunk.
function glbParts(bytes) {
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  const jsonLength = view.getUint32(12, true);
  return { json: JSON.parse(new TextDecoder().decode(bytes.subarray(20, 20 + jsonLength))),
           rest: bytes.subarray(20 + jsonLength) };
}

// The glTF-Validator's report of the asset at `path` (external resources beside it).
async function validated(path, dir = dirname(path)) {
  const bytes = new Uint8Array(readFileSync(path));
  return validator.validateBytes(bytes, {
    uri: path, maxIssues: 1000,
    externalResourceFunction: async (uri) => new Uint8Array(readFileSync(join(dir, decodeURIComponent(uri)))),
  });
}

// Its messages; extensionsUsed's indices left out (the vendor extension's name goes first there).
const messages = (report) => report.issues.messages
  .map((m) => `${m.code} ${(m.pointer ?? "").replace(/^\/extensionsUsed\/\d+$/, "/extensionsUsed")} ${m.message}`).sort();

// The JSON without what matc adds: the extension in each material, its extensionsUsed entry, and
// an `extensions` object left empty by it where the input had none.
function withoutExtension(json, input) {
  const copy = structuredClone(json);
  copy.extensionsUsed = copy.extensionsUsed.filter((name) => name !== kExtension);
  if (copy.extensionsUsed.length === 0 && !input.extensionsUsed) delete copy.extensionsUsed;
  copy.materials.forEach((material, i) => {
    if (!material.extensions) return;
    delete material.extensions[kExtension];
    if (Object.keys(material.extensions).length === 0 && !input.materials[i].extensions) delete material.extensions;
  });
  return copy;
}

const sameJson = (a, b) => JSON.stringify(a) === JSON.stringify(b);

// glTF-Transform's view of an asset: materials with their factors, texture bytes, accessor data.
async function transformView(path) {
  const document = await new NodeIO().setLogger(new Logger(Logger.Verbosity.ERROR))
    .registerExtensions(KHRONOS_EXTENSIONS).read(path);
  const root = document.getRoot();
  return {
    materials: root.listMaterials().map((m) => [m.getName(), m.getBaseColorFactor(), m.getMetallicFactor(),
                                                m.getRoughnessFactor(), [...m.listExtensions()].map((e) => e.extensionName)]),
    textures: root.listTextures().map((t) => Buffer.from(t.getImage()).toString("base64")),
    accessors: root.listAccessors().map((a) => Array.from(a.getArray())),
  };
}

// Each extension against the schema and the compile's <name>.json.
let perPixelMetals = 0;
function checkExtensions(json, build, asset) {
  let count = 0;
  for (const material of json.materials) {
    const extension = material.extensions?.[kExtension];
    if (!extension) continue;
    ++count;
    check(validateExtension(extension), `${asset}: ${material.name}: the schema refuses the extension: ` +
                                        JSON.stringify(validateExtension.errors));
    const compiled = JSON.parse(readFileSync(join(build, `${extension.name}.json`), "utf8"));
    check(sameJson(extension.coefficients, compiled.coefficients), `${asset}: ${extension.name}'s coefficients ` +
          `differ from <name>.json's`);
    check(extension.basis === compiled.basis.name && extension.matcVersion === compiled.matc_version,
          `${asset}: ${extension.name}: basis ${extension.basis} ${extension.matcVersion}`);
    check(!compiled.coat === !extension.coat, `${asset}: ${extension.name}: coat ${!!extension.coat} vs ${!!compiled.coat}`);
    // A textured metal of Schlick's curve carries its coefficients at F0 = 0, and the compile at
    // the factor is F0 (1, 0, 0, 0) + (1 - F0) times them; no other metal carries them.
    const perPixel = material.pbrMetallicRoughness?.baseColorTexture !== undefined && !compiled.coat &&
                     compiled.input?.f82_tint?.tint?.every((value) => value === 1);
    check(perPixel === (extension.zeroF0Coefficients !== undefined),
          `${asset}: ${extension.name}: zeroF0Coefficients ${extension.zeroF0Coefficients ? "given" : "absent"}`);
    if (extension.zeroF0Coefficients) {
      const worst = Math.max(...extension.coefficients.flatMap((row, c) => row.map((value, i) =>
        Math.abs(row[0] * (i === 0 ? 1 : 0) + (1 - row[0]) * extension.zeroF0Coefficients[c][i] - value))));
      check(worst < 1e-12, `${asset}: ${extension.name}: not linear in F0 (${worst})`);
      ++perPixelMetals;
    }
    if (compiled.coat) {
      check(sameJson(extension.coat.underCoatCoefficients, compiled.coat.under_coat_coefficients) &&
            sameJson(extension.coat.coatCoefficients, compiled.coat.coat_coefficients) &&
            extension.coat.ior === compiled.coat.input.ior && extension.coat.weight === compiled.coat.input.weight,
            `${asset}: ${extension.name}'s coat differs from <name>.json's`);
      check(sameJson(extension.maxError, compiled.coat.accuracy.layered.max), `${asset}: ${extension.name} maxError`);
    } else if (compiled.film_table) {
      // A filmed metal carries its film and its table's texels: <name>.json's rows as float32.
      const bytes = Buffer.from(extension.film.table.texels, "base64");
      const rows = [...compiled.film_table.fresnel, ...compiled.film_table.preintegrated].flat();
      const sameTexels = bytes.length === 4 * rows.length &&
                         rows.every((value, i) => bytes.readFloatLE(4 * i) === Math.fround(value));
      check(sameTexels && extension.film.ior === compiled.input.film.ior &&
            extension.film.thickness === compiled.input.film.thickness,
            `${asset}: ${extension.name}'s film differs from <name>.json's`);
      check(sameJson(extension.maxError, compiled.accuracy.film_table.max), `${asset}: ${extension.name} maxError`);
    } else {
      check(sameJson(extension.maxError, compiled.accuracy.decomposition.max), `${asset}: ${extension.name} maxError`);
    }
  }
  return count;
}

const dir = mkdtempSync(join(tmpdir(), "matc-gltf-out-"));
try {
  const car = join(dir, "car.glb");
  await carAsset(car, { foil: true, trim: true });
  await trimAsset(dir);
  const trim = join(dir, "trim.gltf");
  const build = join(dir, "build");
  run(matc, ["-q", "-o", build, "--emit", "json", car, trim]);
  mkdirSync(join(dir, "out"));
  const carOut = join(dir, "out", "car.glb");
  const trimOut = join(dir, "trim_matc.gltf");
  // Into another folder: the files the .gltf names are copied beside it.
  const trimElsewhere = join(dir, "out", "nested", "trim.gltf");
  run(matc, ["gltf", "-q", car, "-o", carOut]);
  run(matc, ["gltf", "-q", trim, "-o", trimOut]);
  run(matc, ["gltf", "-q", trim, "-o", trimElsewhere]);
  const named = JSON.parse(readFileSync(trim, "utf8")).buffers.map((b) => decodeURIComponent(b.uri));
  check(named.length > 0 && named.every((file) => Buffer.compare(readFileSync(join(dir, file)),
                                                                 readFileSync(join(dir, "out", "nested", file))) === 0),
        `${trimElsewhere}: the files ${named} are not copied beside it byte for byte`);
  check(readdirSync(join(dir, "out", "nested")).sort().join() === ["trim.gltf", ...named].sort().join(),
        `${trimElsewhere}: beside it ${readdirSync(join(dir, "out", "nested"))}`);

  let metals = 0;
  for (const [input, output, binary] of [[car, carOut, true], [trim, trimOut, false], [trim, trimElsewhere, false]]) {
    const inBytes = new Uint8Array(readFileSync(input)), outBytes = new Uint8Array(readFileSync(output));
    // The validator: no error; its messages those of the input plus one for the vendor extension.
    const [before, after] = [await validated(input), await validated(output)];
    check(after.issues.numErrors === 0, `${output}: glTF-Validator errors: ${messages(after).join("\n")}`);
    const added = messages(after).filter((m) => !messages(before).includes(m));
    check(added.length === 1 && added[0].startsWith("UNSUPPORTED_EXTENSION") && added[0].includes(kExtension) &&
          after.issues.numWarnings === before.issues.numWarnings,
          `${output}: the validator's messages beyond the input's: ${added.join("; ")}`);
    // Every other byte.
    const [inJson, outJson] = binary ? [glbParts(inBytes).json, glbParts(outBytes).json]
                                     : [JSON.parse(readFileSync(input, "utf8")), JSON.parse(readFileSync(output, "utf8"))];
    check(sameJson(withoutExtension(outJson, inJson), inJson), `${output}: the JSON beside the extension changed`);
    if (binary) check(Buffer.compare(glbParts(inBytes).rest, glbParts(outBytes).rest) === 0, `${output}: the BIN chunk changed`);
    check(outJson.extensionsUsed.includes(kExtension) && !(outJson.extensionsRequired ?? []).includes(kExtension),
          `${output}: extensionsUsed ${outJson.extensionsUsed}, extensionsRequired ${outJson.extensionsRequired}`);
    // glTF-Transform reads it as it reads the input.
    check(sameJson(await transformView(output), await transformView(input)), `${output}: glTF-Transform reads it differently`);
    metals += checkExtensions(outJson, build, output);
    // A second run over the output: the same bytes.
    const again = join(dir, binary ? "again.glb" : "again.gltf");
    run(matc, ["gltf", "-q", output, "-o", again]);
    check(Buffer.compare(readFileSync(again), outBytes) === 0, `${output}: a second run changed the bytes`);
  }
  check(metals === 8, `${metals} metals carry the extension (car: paint, chrome, foil, textured trim; trim: 2, twice)`);
  check(perPixelMetals === 1, `${perPixelMetals} metals carry zeroF0Coefficients (the textured trim)`);

  // An asset without a metal goes through a pipeline: exit 0, a note, the bytes as they were.
  const plastic = join(dir, "plastic.gltf");
  writeFileSync(plastic, JSON.stringify({ asset: { version: "2.0" }, materials: [
    { name: "Rubber", pbrMetallicRoughness: { metallicFactor: 0 } }] }));
  const plain = spawnSync(matc, ["gltf", plastic, "-o", join(dir, "out", "plastic.gltf")], { encoding: "utf8" });
  check(plain.status === 0 && plain.stderr.includes("holds no metal") && plain.stdout.includes("written unchanged") &&
        Buffer.compare(readFileSync(plastic), readFileSync(join(dir, "out", "plastic.gltf"))) === 0,
        `matc gltf of an asset without a metal: exit ${plain.status}, ${plain.stdout}${plain.stderr}`);

  // Refusals: nothing written.
  const refused = (args, status, phrase) => {
    const result = spawnSync(matc, ["gltf", ...args], { encoding: "utf8" });
    check(result.status === status && result.stderr.includes(phrase),
          `matc gltf ${args.join(" ")}: exit ${result.status}, ${result.stderr}`);
  };
  refused([car, "-o", car], 1, "would overwrite its input");
  // A file of the same name with other bytes where the buffer would be copied: another asset's,
  // maybe; never replaced.
  mkdirSync(join(dir, "sub"));
  writeFileSync(join(dir, "sub", named[0]), "the user's");
  refused([trim, "-o", join(dir, "sub", "trim.gltf")], 1, "other bytes");
  refused([car, "-o", join(dir, "out", "car.gltf")], 2, "an output ending in .glb");
  check(!existsSync(join(dir, "sub", "trim.gltf")) && !existsSync(join(dir, "out", "car.gltf")) &&
        readFileSync(join(dir, "sub", named[0]), "utf8") === "the user's", "a refused run wrote its output");
  console.log(`matc gltf: ${metals} metals written into 3 glTF-Transform assets (.glb, .gltf beside its buffer and in ` +
              `another folder with its buffer copied); an asset without a metal written unchanged; ` +
              `glTF-Validator: no errors, only the vendor extension's information added; every other byte ` +
              `carried; glTF-Transform reads the same materials, textures and geometry; a second run gives the same bytes`);
} finally {
  rmSync(dir, { recursive: true, force: true });
}
finish();
