// The npm package (build/matc-<version>.tgz) installed into a fresh project and run from Node:
// its compile of every example material, of the 23 measured metals bare and under 1.3-1.6 coats,
// and of a few materials under other options, against the native library's (the public API, by
// matc_api_dump); its shader texts against the files `matc -o` writes; the bad-input catalogue
// through the JS API (the CLI's located lines, and an instance still usable after each).
//   node check-wasm-package.mjs PACKAGE.tgz MATC MATC_API_DUMP REPO_ROOT
import { execFileSync, spawnSync } from "node:child_process";
import fs from "node:fs";
import { tmpdir } from "node:os";
import path from "node:path";
import { fileURLToPath } from "node:url";
import { gzipSync } from "node:zlib";
import { check, finish } from "./report.mjs";

const [tarball, matc, apiDump, root] = process.argv.slice(2).map((arg) => path.resolve(arg));
const work = fs.mkdtempSync(path.join(tmpdir(), "matc-wasm-"));
const examples = path.join(root, "examples", "materials");
const catalogue = path.join(root, "tests", "data", "bad_inputs");

// A fresh project with nothing but the package, installed from its tarball without the network.
fs.writeFileSync(path.join(work, "package.json"), JSON.stringify({ name: "probe", private: true, type: "module" }));
execFileSync("npm", ["install", "--offline", "--no-audit", "--no-fund", "--loglevel=error", tarball],
             { cwd: work, stdio: "inherit" });
const { createMatc, MatcError } = await import(path.join(work, "node_modules", "matc", "index.mjs"));
// The package's names resolve from a project that installed it (the engine modules need their
// engine, which this project lacks: their files are checked to be there).
const resolved = spawnSync(process.execPath, ["--input-type=module", "-e",
  "const m = await import('matc'); const b = await import('matc/build'); " +
  "console.log(typeof m.createMatc, typeof b.compiledMatcBuildFiles, m.version);"], { cwd: work, encoding: "utf8" });
check(resolved.stdout.trim() === `function function ${JSON.parse(fs.readFileSync(path.join(work, "node_modules", "matc", "package.json"))).version}`,
      `import "matc" and "matc/build" from the project: ${resolved.stdout}${resolved.stderr}`);
for (const file of ["three/matc-three.mjs", "three/matc-three-webgpu.mjs", "three/matc-gltf.mjs", "three/matc-gltf-webgpu.mjs",
                    "three/gltf-plugin.mjs", "babylon/matc-babylon.mjs",
                    "babylon/matc-gltf.mjs", "tables/matc_lut.bin"]) {
  check(fs.existsSync(path.join(work, "node_modules", "matc", file)), `the package lacks ${file}`);
}
check(fs.existsSync(path.join(work, "node_modules", "matc", "tables", "matc_lut.ktx2")), "the package has its LUT");
const matc_ = await createMatc();
// The binary's size target (docs/web.md): at most 1 MiB gzipped.
const wasmBytes = fs.readFileSync(path.join(work, "node_modules", "matc", "matc.wasm"));
const gzipped = gzipSync(wasmBytes, { level: 9 }).length;
check(gzipped <= 1 << 20, `matc.wasm is ${gzipped} bytes gzipped, over 1 MiB`);
console.log(`matc.wasm: ${wasmBytes.length} bytes, ${gzipped} gzipped`);

// The requests: the examples (by their file names, as `matc -o` names them), every preset bare
// and coated, and other options.
const requests = [];
for (const file of fs.readdirSync(examples).filter((f) => f.endsWith(".json")).sort()) {
  requests.push({ text: fs.readFileSync(path.join(examples, file), "utf8"), path: file, example: true });
}
const presets = matc_.spectralPresets();
check(presets.length >= 23, `the measured metals: ${presets.length}`);
for (const preset of presets) {
  const name = `p_${preset.toLowerCase()}`;
  requests.push({ text: JSON.stringify({ name, spectral: { preset } }), path: `${name}.json` });
  for (const ior of [1.3, 1.4, 1.5, 1.6]) {
    requests.push({ text: JSON.stringify({ name: `${name}_coat`, spectral: { preset }, coat: { ior, roughness: 0.1 } }),
                    path: `${name}_coat.json` });
  }
}
for (const options of [{ basis: "paper" }, { basis: "extended" }, { basis: "f82" }, { colorSpace: "acescg" },
                       { gamutMapping: "desaturate" }]) {
  requests.push({ text: JSON.stringify({ name: "cu", spectral: { preset: "Cu" } }), path: "cu.json", options });
  requests.push({ text: fs.readFileSync(path.join(examples, "figure2_edge_tint.json"), "utf8"),
                  path: "figure2_edge_tint.json", options });
}

// Native: the same requests through matc_api_dump (relative spectral files resolve against the
// examples folder: it runs there).
const native = execFileSync(apiDump, {
  cwd: examples, maxBuffer: 1 << 30, encoding: "utf8",
  input: requests.map((r) => JSON.stringify({ text: r.text, path: r.path, options: r.options ?? {} })).join("\n") + "\n",
}).trim().split("\n").map((line) => JSON.parse(line));

const cosines = Array.from({ length: 65 }, (_, i) => i / 64);
const pairs = [0.05, 0.3, 0.7, 1.0].flatMap((n) => [0.0, 0.25, 0.6, 1.0].map((r) => [n, r]));
const largest = { coefficients: 0, fresnel: 0, exact: 0, fbar: 0 };
const maxDifference = (a, b) => a.reduce((m, v, i) => Math.max(m, Math.abs(v - b[i])), 0);
// Two texts that differ only in the last digits of their numbers (the coefficients, where the math
// libraries differ in the last bits): the largest difference of their numbers, or Infinity when
// anything else differs.
const kNumber = /-?\d+\.\d+(?:e[-+]?\d+)?/g;
function numbersApart(a, b) {
  if (a.replace(kNumber, "#") !== b.replace(kNumber, "#")) return Infinity;
  const x = a.match(kNumber) ?? [], y = b.match(kNumber) ?? [];
  return x.reduce((m, v, i) => Math.max(m, Math.abs(Number(v) - Number(y[i]))), 0);
}
let largestInTexts = 0;
let materials = 0, bitIdentical = 0, unreadable = 0;
const sameTexts = { glsl: 0, hlsl: 0, wgsl: 0, json: 0 };
const wasmTexts = new Map();  // example file name -> { glsl, hlsl, wgsl, json } for the CLI comparison

requests.forEach((request, index) => {
  const expected = native[index];
  let compiled;
  try {
    compiled = matc_.parseMaterials(request.text, request.path).map((m) => matc_.compile(m, request.options));
  } catch (error) {
    // A material naming a spectral CSV: the WebAssembly library has no file system to read it.
    const namesFile = /"file"\s*:/.test(request.text);
    check(error instanceof MatcError && namesFile && /cannot read/.test(error.message),
          `${request.path}: ${error.message}`);
    unreadable += 1;
    return;
  }
  check(!expected.error && expected.materials.length === compiled.length, `${request.path}: native ${expected.error ?? ""}`);
  compiled.forEach((material, m) => {
    const reference = expected.materials[m];
    materials += 1;
    const rows = (values) => values.flatMap((row) => Array.from(row));
    const ours = rows(material.coefficients);
    const theirs = rows(reference.coefficients);
    if (material.coat) {
      ours.push(...rows(material.coat.underCoatCoefficients), ...material.coat.coatCoefficients);
      theirs.push(...rows(reference.under_coat_coefficients), ...reference.coat_coefficients);
    }
    const identical = ours.every((v, i) => v === theirs[i]);
    bitIdentical += identical ? 1 : 0;
    largest.coefficients = Math.max(largest.coefficients, maxDifference(ours, theirs));
    largest.fresnel = Math.max(largest.fresnel, maxDifference(material.fresnel(cosines), reference.fresnel));
    largest.exact = Math.max(largest.exact, maxDifference(material.exact(cosines), reference.exact));
    largest.fbar = Math.max(largest.fbar, maxDifference(material.fbar(pairs.map((p) => p[0]), pairs.map((p) => p[1])),
                                                        reference.fbar));
    const texts = matc_.textOutputs(request.options);
    const mine = { glsl: texts.materialSource("glsl", material), hlsl: texts.materialSource("hlsl", material),
                   wgsl: texts.materialSource("wgsl", material), json: texts.materialJson(material) };
    for (const [kind, text] of Object.entries(mine)) {
      if (text === reference.texts[kind]) {
        sameTexts[kind] += 1;
      } else {
        check(!identical, `${request.path} ${material.name}.${kind}: differs with bit-identical coefficients`);
        const apart = numbersApart(text, reference.texts[kind]);
        check(apart <= 1e-9, `${request.path} ${material.name}.${kind}: differs beyond its numbers' last digits`);
        largestInTexts = Math.max(largestInTexts, apart);
      }
    }
    if (request.example) wasmTexts.set(material.name, { texts: mine, identical });
  });
});
check(largest.coefficients <= 1e-9, `coefficients differ by ${largest.coefficients}`);
check(largest.fresnel <= 1e-9 && largest.exact <= 1e-9 && largest.fbar <= 1e-9,
      `curves differ by ${JSON.stringify(largest)}`);
console.log(`compared ${materials} materials (${bitIdentical} with bit-identical coefficients; ${unreadable} ` +
            `naming a file refused); largest differences: ${JSON.stringify(largest)}; ` +
            `texts identical of ${materials}: ${JSON.stringify(sameTexts)}, the others apart by at most ` +
            `${largestInTexts} in a printed number`);

// The texts against `matc -o`'s files for the examples.
const out = path.join(work, "out");
execFileSync(matc, ["-q", "--emit", "glsl,hlsl,wgsl,json", "-o", out,
                    ...fs.readdirSync(examples).filter((f) => f.endsWith(".json")).sort().map((f) => path.join(examples, f))],
             { stdio: ["ignore", "pipe", "pipe"] });
const library = matc_.textOutputs();
for (const language of ["glsl", "hlsl", "wgsl"]) {
  check(library.librarySource(language) === fs.readFileSync(path.join(out, `matc_fresnel.${language}`), "utf8"),
        `matc_fresnel.${language} differs from matc's`);
}
let files = 0, sameFiles = 0;
for (const [name, { texts, identical }] of wasmTexts) {
  for (const [kind, text] of Object.entries(texts)) {
    const written = fs.readFileSync(path.join(out, `${name}.${kind}`), "utf8");
    files += 1;
    sameFiles += text === written ? 1 : 0;
    // Byte for byte wherever the coefficients are bit for bit; elsewhere in the last digits only.
    if (identical) check(text === written, `${name}.${kind} differs from matc's`);
    else check(numbersApart(text, written) <= 1e-9, `${name}.${kind} differs from matc's beyond its numbers`);
  }
}
console.log(`${files} material files compared with matc -o (${sameFiles} byte for byte), and the 3 libraries`);

// The bad-input catalogue: every case that is one material file or glTF asset and a plain
// `matc -o out case` (no other arguments, no set-up, no spectral file), through parseMaterials
// and compile.
let cases = 0;
// Rules of a build directory, which the JS API does not write: names that would overwrite the
// shared files.
const kOutputDirectoryRules = new Set(["name_reserved", "name_reserved_coefficient_table"]);
const plainArguments = (name, file) => {
  const args = path.join(catalogue, `${name}.args`);
  return !fs.existsSync(args) || fs.readFileSync(args, "utf8").trim() === `-o out ${file}`;
};
for (const file of fs.readdirSync(catalogue).filter((f) => /\.(json|mtlx|gltf)$/.test(f) && fs.statSync(path.join(catalogue, f)).isFile()).sort()) {
  const name = file.replace(/\.(json|mtlx|gltf)$/, "");
  if (!plainArguments(name, file) || fs.existsSync(path.join(catalogue, `${name}.setup`)) ||
      !fs.existsSync(path.join(catalogue, `${name}.expected`)) || kOutputDirectoryRules.has(name)) continue;
  const bytes = new Uint8Array(fs.readFileSync(path.join(catalogue, file)));  // as they are, UTF-8 or not
  const text = Buffer.from(bytes).toString("latin1");
  const [status, ...lines] = fs.readFileSync(path.join(catalogue, `${name}.expected`), "utf8").trimEnd().split("\n");
  cases += 1;
  let shown = "";
  let thrown = null;
  let parsed = null;
  try {
    parsed = matc_.parseMaterials(bytes, file);
    for (const material of parsed) {
      const compiled = matc_.compile(material);
      shown += compiled.diagnostics.map((d) => d.text).join("\n") + "\n";
    }
  } catch (error) {
    thrown = error;
    shown = error.message;
  }
  if (/"file"\s*:/.test(text)) {
    check(thrown instanceof MatcError || status === "exit 0", `${file}: ${shown}`);
  } else {
    check((status === "exit 0") === (thrown === null), `${file}: ${status}, but ${thrown ? "threw" : "did not throw"}: ${shown}`);
    if (thrown) check(thrown instanceof MatcError && thrown.kind === "material", `${file}: not a MatcError: ${thrown}`);
    // A glTF asset without a metal parses to no material: its notes are only the CLI's to print.
    const noMaterial = parsed?.length === 0 && status === "exit 0";
    if (!noMaterial) for (const line of lines) check(shown.includes(line), `${file}: missing ${line}\n  got: ${shown}`);
  }
  check(!/[\x00-\x09\x0b-\x1f\x7f]/.test(shown), `${file}: a control character in the message`);
  // The instance still works.
  check(matc_.compile(matc_.parseMaterial({ name: "probe", ior: { n: 1.5, k: 3 } })).coefficients.length === 3,
        `${file}: the instance no longer compiles`);
}
console.log(`${cases} catalogue cases through the JS API`);

// MATC_materials_fresnel as the glTF loaders read it (matc/build's gltfExtensionMaterial): a
// hostile member is refused naming it, never handed to a shader.
{
  const { gltfExtensionMaterial } = await import(path.join(work, "node_modules", "matc", "matc-build.mjs"));
  const build = { basis: "powers", manifest: { matc_version: "1.2.3" } };
  const rows = (row) => [row, row, row];
  const good = { name: "Trim", basis: "powers", matcVersion: "1.2.3", coefficients: rows([0.9, 0.1, 0.03, 0.1]),
                 zeroF0Coefficients: rows([0, 1, 0.32, 0.99]) };
  const read = await gltfExtensionMaterial(build, good);
  check(JSON.stringify(read.zeroF0Coefficients) === JSON.stringify(good.zeroF0Coefficients),
        `a good extension's zeroF0Coefficients: ${JSON.stringify(read.zeroF0Coefficients)}`);
  // An edge-coloured textured metal's F0 table: 33 entries of 3 rows.
  const entries = (row) => Array.from({ length: 33 }, () => rows(row));
  const table = { coefficients: entries([0.5, 0.5, 0.1, 0.2]) };
  const readTable = await gltfExtensionMaterial(build, { ...good, zeroF0Coefficients: undefined, f0Table: table });
  check(JSON.stringify(readTable.f0Table) === JSON.stringify(table), "a good extension's f0Table");
  const refusals = [
    [{ zeroF0Coefficients: rows([0, 1, NaN, 0.99]) }, /zeroF0Coefficients must be rows \[0, 1, c_2, c_3\] of finite numbers/],
    [{ zeroF0Coefficients: rows([0, 1, "0.3", 0.99]) }, /zeroF0Coefficients must be rows/],
    [{ zeroF0Coefficients: rows([0.1, 0.9, 0.3, 0.99]) }, /zeroF0Coefficients must be rows/],
    [{ zeroF0Coefficients: [[0, 1, 0.3, 0.9]] }, /zeroF0Coefficients must be 3 rows of 4 numbers/],
    [{ zeroF0Coefficients: "rows" }, /zeroF0Coefficients must be 3 rows of 4 numbers/],
    [{ coefficients: rows([0.9, 0.1, Infinity, 0.1]) }, /coefficients must be finite numbers/],
    [{ f0Table: { coefficients: entries([0.5, 0.5, 0.1, 0.2]).slice(1) } }, /f0Table\.coefficients must be 33 entries of 3 rows of 4 numbers/],
    [{ f0Table: "table" }, /f0Table\.coefficients must be 33 entries/],
    [{ f0Table: { coefficients: entries([0.5, 0.5, NaN, 0.2]) } }, /f0Table\.coefficients must be finite numbers/],
    [{ f0Table: { coefficients: entries([0.5, 0.5, "0.1", 0.2]) } }, /f0Table\.coefficients must be finite numbers/],
    [{ f0Table: { coefficients: entries([0.5, 0.5, 0.1]) } }, /f0Table: coefficients must be 3 rows of 4 numbers/],
    [{ f0Table: { ...table, underCoatCoefficients: table.coefficients } }, /a bare metal's table has no underCoatCoefficients/],
    [{ f0Table: table, coat: { weight: 1 } }, /a coated metal's table needs underCoatCoefficients/],
    [{ name: "a;b" }, /name is not the identifier matc writes/],
    [{ name: "a__b" }, /name is not the identifier matc writes/],
    [{ name: "_trim" }, /name is not the identifier matc writes/],
    [{ name: "sum" }, /name is not the identifier matc writes/],
    [{ name: "f82" }, /name is not the identifier matc writes/],
    [{ name: "t".repeat(65) }, /name is not the identifier matc writes/],
    [{ basis: "paper" }, /holds coefficients of basis "paper"/],
  ];
  for (const [change, pattern] of refusals) {
    let message = "no error";
    try {
      await gltfExtensionMaterial(build, { ...good, ...change });
    } catch (error) {
      message = error.message;
    }
    check(pattern.test(message), `MATC_materials_fresnel ${JSON.stringify(change)}: ${message}`);
  }
}

// What the glTF loaders make of a textured metal's extension (matc/build's gltfMetals): Schlick's
// curve per pixel from zeroF0Coefficients, an edge-coloured metal from its f0Table, and one with
// neither (compiled in another working space) at its factor, with a note that says so.
{
  const { gltfMetals } = await import(path.join(work, "node_modules", "matc", "matc-build.mjs"));
  const build = { basis: "powers", manifest: { matc_version: "0.1.0" } };
  const rows = (row) => [row, row, row];
  const extension = { name: "Trim", basis: "powers", matcVersion: "0.1.0", coefficients: rows([0.9, 0.1, 0.03, 0.1]) };
  const textured = (fresnel) => ({ name: "Trim", pbrMetallicRoughness: { metallicFactor: 1, baseColorTexture: { index: 0 } },
                                   extensions: { MATC_materials_fresnel: fresnel } });
  const json = { materials: [
    textured({ ...extension, zeroF0Coefficients: rows([0, 1, 0.32, 0.99]) }),
    textured({ ...extension, f0Table: { coefficients: Array.from({ length: 33 }, () => rows([0.5, 0.5, 0.1, 0.2])) } }),
    textured({ ...extension, colorSpace: "acescg" }),
  ] };
  const notes = [], warnings = [];
  const metals = gltfMetals({ build, json, warn: (index, why) => warnings.push([index, why]),
                              note: (index, why) => notes.push([index, why]) });
  const [schlick, table, factor] = await Promise.all([0, 1, 2].map((index) => metals.metalOf(index)));
  check(schlick?.source.schlick?.zeroF0Coefficients?.length === 3, "a textured Schlick metal: the { schlick } source");
  check(table?.source.f0Table?.coefficients?.length === 33 && table.source.material?.name === "Trim",
        "a textured edge-coloured metal: the { material, f0Table } source");
  check(factor?.source.material?.name === "Trim" && !factor.source.f0Table && !factor.source.schlick,
        "a textured metal without per-pixel data: its factor");
  check(notes.length === 1 && notes[0][0] === 2 && /baseColorTexture is not followed/.test(notes[0][1]) &&
        warnings.length === 0, `the notes: ${JSON.stringify(notes)}, warnings: ${JSON.stringify(warnings)}`);
}

// A coated metal from its MATC_materials_fresnel alone (no compiler in the page, no build directory
// of the asset): matc's template filled with the extension's values is the compiler's snippet,
// comment lines aside (they name the source and the fits' errors), in GLSL (WebGL) and WGSL
// (WebGPU): a full clear coat, a partial tinted one, a partial clear one at another index.
for (const language of ["glsl", "wgsl"]) {
  const { gltfExtensionMaterial } = await import(path.join(work, "node_modules", "matc", "matc-build.mjs"));
  const texts = matc_.textOutputs();
  const build = { basis: "powers", manifest: { matc_version: "0.1.0" }, url: "test", language,
                  library: texts.librarySource(language) };
  const code = (snippet) => snippet.split("\n").filter((line) => !/^\s*\/\//.test(line)).join("\n");
  const rows = (values) => values.map((row) => Array.from(row));
  for (const coat of [{ weight: 1, ior: 1.5, roughness: 0.03 },
                      { weight: 0.6, ior: 1.6, roughness: 0.2, color: [0.9, 0.7, 0.35] },
                      { weight: 0.4, ior: 1.3, roughness: 0.1 }]) {
    const compiled = matc_.compile(matc_.parseMaterial({ name: "lacquer", f82_tint: { f0: [0.93, 0.62, 0.52], tint: [0.9, 0.8, 0.7] },
                                                         coat }));
    const extension = {
      name: compiled.name, basis: compiled.basis, matcVersion: "0.1.0", colorSpace: "lin_rec709",
      coefficients: rows(compiled.coefficients), maxError: Array.from(compiled.coat.layeredMaxError),
      coat: { weight: compiled.coat.weight, ior: compiled.coat.ior, roughness: compiled.coat.roughness,
              color: Array.from(compiled.coat.color), underCoatCoefficients: rows(compiled.coat.underCoatCoefficients),
              coatCoefficients: Array.from(compiled.coat.coatCoefficients) },
    };
    const material = await gltfExtensionMaterial(build, extension);
    const compilers = texts.materialSource(language, compiled);
    check(code(material.coat.snippet) === code(compilers),
          `${language}, coat ${JSON.stringify(coat)}: the snippet from the extension is not the compiler's:\n${material.coat.snippet}\n--\n${compilers}`);
    check(material.coat.snippet.includes("from MATC_materials_fresnel"), "the snippet from the extension says so");
    for (const [change, pattern] of [[{ weight: 2 }, /coat\.weight must be a number in \[0, 1\]/],
                                     [{ ior: "1.5" }, /coat\.ior must be a number in \[1\.05, 3\]/],
                                     [{ color: [1, 1] }, /coat\.color must be 3 numbers/],
                                     [{ coatCoefficients: [0.04, 0.96, NaN, 0.1] }, /coatCoefficients \(one row\) must be 4 finite numbers/]]) {
      let message = "no error";
      try {
        await gltfExtensionMaterial(build, { ...extension, coat: { ...extension.coat, ...change } });
      } catch (error) {
        message = error.message;
      }
      check(pattern.test(message), `MATC_materials_fresnel.coat ${JSON.stringify(change)}: ${message}`);
    }
    compiled.dispose();
  }
  // A filmed metal's extension (matc gltf's, from KHR_materials_iridescence on a metal): its table's
  // texels (base64 float32) become the texels compileGltf's material holds, to float precision; malformed members are
  // refused with the member named.
  const foil = JSON.stringify({ asset: { version: "2.0" }, extensionsUsed: ["KHR_materials_iridescence"], materials: [{
    name: "Foil", pbrMetallicRoughness: { baseColorFactor: [0.9, 0.9, 0.9, 1], metallicFactor: 1 },
    extensions: { KHR_materials_iridescence: { iridescenceFactor: 1, iridescenceThicknessMaximum: 350 } } }] });
  const written = matc_.compileGltf(foil, "foil.gltf", { basis: "powers" });
  const foilExtension = JSON.parse(new TextDecoder().decode(written.bytes)).materials[0].extensions.MATC_materials_fresnel;
  const filmedMaterial = await gltfExtensionMaterial(build, foilExtension);
  const texels = written.materials[0].filmTable.texels;
  check(filmedMaterial.film?.table.size === 65 && filmedMaterial.film.table.height === 18 &&
        filmedMaterial.film.table.data.every((value, i) => Math.abs(value - texels[i]) <= 6e-8 * Math.max(1, Math.abs(value))),
        `${language}: the extension's film table is not the compiled one`);
  const withFilm = (change) => ({ ...foilExtension, film: { ...foilExtension.film, ...change } });
  const withTable = (change) => withFilm({ table: { ...foilExtension.film.table, ...change } });
  // The texels with one value changed (a NaN: not finite).
  const texelBytes = Buffer.from(foilExtension.film.table.texels, "base64");
  texelBytes.writeFloatLE(NaN, 4 * 7);
  const tableShape = /film\.table must be 65 x 18 texels, their RGB as 14040 bytes of little-endian float32 in base64/;
  for (const [extension, pattern] of [
    [{ ...foilExtension, film: 7 }, /film must be an object/],
    [withFilm({ weight: 2 }), /film\.weight must be a number in \[0, 1\]/],
    [withFilm({ thickness: -1 }), /film\.thickness must be a number in \[0, 2000\]/],
    [withFilm({ ior: "1.3" }), /film\.ior must be a number in \[1, 3\]/],
    [withTable({ texels: foilExtension.film.table.texels.slice(4) }), tableShape],
    [withTable({ texels: `${foilExtension.film.table.texels.slice(1)}!` }), tableShape],
    [withTable({ width: 64 }), tableShape],
    [withTable({ texels: texelBytes.toString("base64") }), /film\.table\.texels must be finite numbers/],
    [withFilm({ table: null }), tableShape],
    // A film under a coat is checked as any coat is (docs/thin-film.md, "Under a coat"); per-pixel
    // data beside a film is what matc does not write.
    [{ ...foilExtension, coat: {} }, /coat: underCoatCoefficients must be 3 rows of 4 numbers/],
    [{ ...foilExtension, zeroF0Coefficients: [[0, 1, 0, 0], [0, 1, 0, 0], [0, 1, 0, 0]] }, /a film with per-pixel data/],
  ]) {
    let message = "no error";
    try {
      await gltfExtensionMaterial(build, extension);
    } catch (error) {
      message = error.message;
    }
    check(pattern.test(message), `${language}: MATC_materials_fresnel.film bad: ${message}`);
  }
  written.materials.forEach((material) => material.dispose());
}

// Arguments: refused with the argument named, the instance usable after.
const gold = matc_.compile(matc_.parseMaterial({ name: "gold", spectral: { preset: "Au" } }));
const throwsWith = (call, pattern, what) => {
  try {
    call();
    check(false, `${what}: no error`);
  } catch (error) {
    check(pattern.test(error.message), `${what}: ${error.message}`);
  }
};
throwsWith(() => gold.fresnel([0.5, 2]), /mu: element 1 is 2; a number in \[0, 1\]/, "mu out of range");
// The in-page build reads the package's staged tables: the default build's, a layer per basis
// (Node's fetch reads no file: URL, so one is given here), each material on its basis' layer; a
// one-basis library is refused with those tables, before it could read them at the wrong width.
{
  const { compiledMatcBuildFiles } = await import(path.join(work, "node_modules", "matc", "matc-build.mjs"));
  const nodeFetch = globalThis.fetch;
  globalThis.fetch = async (url) => (String(url).startsWith("file:")
      ? new Response(fs.readFileSync(fileURLToPath(url))) : nodeFetch(url));
  try {
    const files = await compiledMatcBuildFiles(matc_);
    check(files.basis === "auto" && files.layers?.join() === "powers,f82" && files.lut.size === 256 &&
          files.lut.height === 128, `the package's tables: basis ${files.basis}, layers ${files.layers}, ` +
          `${files.lut.size}x${files.lut.height}`);
    const tinted = matc_.compile(matc_.parseMaterial({ name: "tinted", f82_tint: { f0: 0.9, tint: 0.5 } }));
    const loaded = await files.loadMaterial(tinted);
    check(loaded.basis === "f82" && (await files.loadMaterial(gold)).basis === "powers",
          `in-page materials' bases: ${loaded.basis}, gold's`);
    tinted.dispose();
    try {
      await compiledMatcBuildFiles(matc_, { options: { basis: "powers" } });
      check(false, "compiledMatcBuildFiles of basis powers with the package's tables: no error");
    } catch (error) {
      check(/a table of basis auto, but options.basis gives basis powers/.test(error.message),
            `compiledMatcBuildFiles of basis powers: ${error.message}`);
    }
  } finally {
    globalThis.fetch = nodeFetch;
  }
}
throwsWith(() => gold.fresnel([NaN]), /mu: element 0 is nan/, "NaN");
throwsWith(() => gold.fresnel("0.5"), /mu: a number or an array/, "a string mu");
throwsWith(() => gold.fbar([0.5], [0.5, 0.5]), /one roughness per NdotV/, "fbar lengths");
throwsWith(() => matc_.compile(gold.material, { basis: "nope\u001b[31m" }), /basis: 'nope\\x1B\[31m' is not one of auto, powers/, "basis");
throwsWith(() => matc_.compile(gold.material, { colour: "x" }), /unknown option 'colour'/, "an unknown option");
throwsWith(() => matc_.textOutputs().materialSource("msl", gold), /language: 'msl' is not one of glsl, hlsl, wgsl/, "language");
throwsWith(() => matc_.parseMaterial(42), /input: a string/, "a number as the input");
const cyclic = {};
cyclic.self = cyclic;
throwsWith(() => matc_.parseMaterial(cyclic), /not representable as JSON/, "a cyclic object");
throwsWith(() => matc_.parseMaterial("{\"name\": \"a\0b\"}"), /error/, "a NUL");
throwsWith(() => matc_.parseMaterial("\uD800"), /error/, "a lone surrogate");
throwsWith(() => matc_.compileGltf(42), /bytes: a string/, "a number as a glTF asset");
throwsWith(() => matc_.compileGltf("{}", "a.json"), /path: 'a.json' names no glTF asset/, "compileGltf of a .json");
throwsWith(() => matc_.compileGltf("{\"asset\": {\"version\": \"2.0\"}, \"materials\": [{\"name\": \"a\", \"name\": \"b\"}]}", "a.gltf"),
           /materials\[0\]\.name: given twice/, "compileGltf of a key given twice");
throwsWith(() => matc_.compileGltf("glTF", "a.glb", { basis: "f82", gamutMapping: 1 }), /options.gamutMapping: a string/,
           "compileGltf's options");
throwsWith(() => matc_.parseMaterials("{}", "m.json", { files: { "../x.csv": "1" } }),
           /files: '\.\.\/x\.csv': a path that leaves the input's folder/, "a file name climbing out");
throwsWith(() => matc_.parseMaterials("{}", "m.json", { files: [] }), /files: an object/, "files as an array");
throwsWith(() => matc_.parseMaterials("{}", "m.json", { files: { "a.csv": 5 } }), /files\["a.csv"\]: a string/,
           "a file that is a number");
{
  // A spectral material's CSV given in memory: the same coefficients as the native library's from
  // the disk; not given, it cannot be read.
  const text = fs.readFileSync(path.join(root, "examples", "materials", "gold_measured_file.json"));
  const csv = fs.readFileSync(path.join(root, "examples", "materials", "spectra", "gold_pbrt_v4.csv"));
  const [measured] = matc_.parseMaterials(text, "gold_measured_file.json", { files: { "spectra/gold_pbrt_v4.csv": csv } });
  const [fromDisk] = execFileSync(apiDump, {  // the native library, reading the CSV from the disk
    cwd: examples, encoding: "utf8",
    input: JSON.stringify({ text: text.toString("utf8"), path: "gold_measured_file.json", options: {} }) + "\n",
  }).trim().split("\n").map((line) => JSON.parse(line));
  const ours = matc_.compile(measured).coefficients.flatMap((row) => Array.from(row));
  const theirs = fromDisk.materials[0].coefficients.flat();
  check(maxDifference(ours, theirs) <= 1e-9,
        `the spectral file given in memory: coefficients ${maxDifference(ours, theirs)} from the disk's`);
  throwsWith(() => matc_.parseMaterials(text, "gold_measured_file.json", { files: {} }), /not among the files given/,
             "a spectral file not given");
}
check(gold.fresnel(1).length === 3, "usable after the refusals");
const coated = matc_.compile(matc_.parseMaterial({ name: "c", spectral: { preset: "Cu" }, coat: { ior: 1.5 } }));
const lobes = coated.coatedFresnel([0.25, 1]);
const total = coated.fresnel([0.25, 1]);
check(lobes.base.length === 6 && lobes.coat.length === 2 &&
      total.every((v, i) => Math.abs(v - (lobes.base[i] + lobes.coat[Math.floor(i / 3)])) < 1e-15),
      "a coated material's lobes sum to its F");
throwsWith(() => gold.coatedFresnel([0.5]), /has no coat/, "lobes of a bare metal");
// A filmed metal's own table (docs/thin-film.md): RGBA texels to upload, row 0 its F at
// mu = (i / 64)^2, as fresnel() reads them.
const filmed = matc_.compile(matc_.parseMaterial({ name: "f", spectral: { preset: "Ti" },
                                                   film: { ior: 2.3, thickness: 300 } }));
const film = filmed.filmTable;
const nodes = Array.from({ length: 65 }, (_, i) => (i / 64) ** 2);
const direct = filmed.fresnel(nodes);
check(film && film.width === 65 && film.height === 18 && film.texels instanceof Float32Array &&
      film.texels.length === 65 * 18 * 4 &&
      nodes.every((_, i) => [0, 1, 2].every((c) => Math.abs(film.texels[4 * i + c] - direct[3 * i + c]) < 1e-6)),
      "a filmed metal's table: 65 x 18 RGBA, row 0 its F");
check(gold.filmTable === null, "a bare metal has no film table");
filmed.dispose();
gold.dispose();
throwsWith(() => gold.fresnel(0.5), /used after dispose/, "after dispose()");

// The declarations: a strict TypeScript program against the installed package; each
// @ts-expect-error line must be an error, so declarations of `any` fail the check too.
fs.writeFileSync(path.join(work, "usage.ts"), `
import { createMatc, MatcError, type CompiledMaterial, type Diagnostic } from "matc";
const matc = await createMatc();
const gold: CompiledMaterial = matc.compile(matc.parseMaterial({ name: "gold", spectral: { preset: "Au" } }),
                                            { basis: "powers", colorSpace: "acescg" });
const f: Float64Array = gold.fresnel([0, 0.5, 1]);
const red: Float64Array = gold.coefficients[0];
const glsl: string = matc.textOutputs().materialSource("glsl", gold);
const first: Diagnostic | undefined = gold.diagnostics[0];
try { matc.parseMaterials("{}"); } catch (error) { if (error instanceof MatcError) console.log(error.diagnostics.length); }
// @ts-expect-error: a language matc does not write
matc.textOutputs().materialSource("msl", gold);
// @ts-expect-error: cosines are numbers
gold.fresnel("0.5");
// @ts-expect-error: compile takes a Material
matc.compile(gold);
console.log(f, red, glsl, first, gold.accuracy.maxError, gold.coat?.ior);
`);
const tsc = spawnSync(path.join(root, "tests", "js", "node_modules", ".bin", "tsc"),
                      ["--strict", "--noEmit", "--target", "es2022", "--module", "es2022", "--moduleResolution", "bundler",
                       "--lib", "es2022,dom", "usage.ts"], { cwd: work, encoding: "utf8" });
check(tsc.status === 0, `tsc on the declarations: ${tsc.stdout}${tsc.stderr}`);

fs.rmSync(work, { recursive: true, force: true });
finish();
