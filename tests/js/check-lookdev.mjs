// The look-development page (js/package/lookdev/, docs/lookdev.md), served from the staged npm
// package as a project's node_modules and driven through its controls in headless Chromium
// (lookdev-check-page.mjs). For materials chosen as a person would (a preset, a colour-picker
// metal in ACEScg, typed n and k, a coated metal, a filmed one, a pasted material file, a pasted MaterialX
// document and a pasted glTF asset of several metals, one chosen, a .gltf dropped with its buffer,
// a .glb whose metals take their metalness from a texture or a factor):
//   - no console error or warning, no uncaught exception;
//   - the probe pixels of the page's matc material (its three.js material, under the engine checks'
//     environment, point and rect lights) equal the CPU runtime's (`matc eval`), to 1e-4;
//   - the plotted curves equal the native library's (`matc eval`'s F and F_exact; the public API's
//     Schlick and F82-tint through matc_api_dump), to 1e-12;
//   - the exports: the snippets equal `matc -o`'s files byte for byte for the exported material
//     file, and <name>.json equals matc's up to the last digits of its numbers (the largest
//     difference is reported: glibc's and emscripten's libm round differently, docs/web.md);
//   - each refused value shows its located message beside its control, marks the control, and
//     keeps the last good material (coefficients, link);
//   - the page's link reproduces a material (a second load from the coated case's URL), and a
//     broken link opens the default metal with its reason;
//   - the dropped .glb shows in the asset view, loaded by matc's glTF plugin beside three.js's own
//     GLTFLoader, and each of its materials on the probe plane is right: a texel of metalness 0 as
//     three.js's own material, the full metal as the CPU runtime's, half metal and the factor 0.3
//     as the mix (glTF's metal-rough model per pixel, docs/gltf.md);
//   - the page and its assets stay under 200 KiB.
//   node check-lookdev.mjs MATC NPM_DIR MATC_API_DUMP
import { execFileSync } from "node:child_process";
import { mkdirSync, mkdtempSync, readdirSync, readFileSync, rmSync, statSync, writeFileSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { compareProbes, expectedProbes, kPointLight, kProbePixels, kProbeRectLight, kProbeSize,
         kThreeJsProbeTerms } from "./engine-probes.mjs";
import { kMetalRough, metalRoughAsset } from "./gltf-assets.mjs";
import { runLookdevPage } from "./lookdev-page.mjs";
import { check, finish } from "./report.mjs";
import { run } from "./shader-cases.mjs";

const [matc, npmDir, apiDump] = process.argv.slice(2);
const kSizeLimit = 200 * 1024;
// A smaller window than a desktop's: each step draws the page's view on Chromium's CPU rasteriser,
// and the checks read the probe renders, curves and exports, not the view.
const kWindowSize = "800,600";
const lights = ["environment", "point", "rect"];
const select = (selector, value) => ({ selector, value, event: "change" });
const input = (selector, value) => ({ selector, value });
const ior = (field, channel, value) => input(`[data-field='ior.${field}'][data-channel='${channel}']`, value);

const kMaterialX = `<?xml version="1.0"?>
<materialx version="1.39" colorspace="lin_rec709">
  <standard_surface name="SR_gold" type="surfaceshader">
    <input name="base_color" type="color3" value="0.944, 0.776, 0.373" />
    <input name="metalness" type="float" value="1" />
    <input name="specular_roughness" type="float" value="0.3" />
  </standard_surface>
  <surfacematerial name="gold_standard_surface" type="material">
    <input name="surfaceshader" type="surfaceshader" nodename="SR_gold" />
  </surfacematerial>
  <open_pbr_surface name="SR_copper" type="surfaceshader">
    <input name="base_color" type="color3" value="0.926, 0.721, 0.504" />
    <input name="base_metalness" type="float" value="1" />
    <input name="specular_color" type="color3" value="0.996, 0.957, 0.823" />
    <input name="specular_roughness" type="float" value="0.3" />
  </open_pbr_surface>
  <surfacematerial name="copper_openpbr" type="material">
    <input name="surfaceshader" type="surfaceshader" nodename="SR_copper" />
  </surfacematerial>
</materialx>
`;

// The cases, each through the page's controls. Probes need roughness 0.3 (engine-probes.mjs).
const kCases = [
  { key: "preset", name: "Cr", bare: true, steps: [input("#preset", "Cr")], lights,
    refusals: [{ key: "name", steps: [input("#name", "9lives")], restore: [input("#name", "Cr")],
                 messageSelector: ".message[data-for='name']", control: "#name",
                 phrase: "material.json:2:11: error: name: '9lives' is not an identifier" }] },
  { key: "colour pickers in ACEScg", name: "tinted", bare: true, colorSpace: "acescg",
    steps: [select("#model", "artistic"), input("#reflectivity", "#e8b890"), input("#edge-tint", "#ffc070"),
            input("#name", "tinted"), select("#color-space", "acescg")], lights },
  { key: "typed n and k", name: "typed", bare: true,
    steps: [select("#model", "ior"), input("#name", "typed"), ior("n", 0, "0.2"), ior("n", 1, "0.9"),
            ior("n", 2, "1.1"), ior("k", 0, "3.9"), ior("k", 1, "2.5"), ior("k", 2, "2.3"),
            select("#color-space", "lin_rec709")], lights,
    refusals: [{ key: "n out of range", steps: [ior("n", 1, "2000")], restore: [ior("n", 1, "0.9")],
                 messageSelector: ".message[data-for='ior']", control: "[data-field='ior.n'][data-channel='1']",
                 phrase: "ior.n[1]: 2000 is out of range; a number in [0, 1000]" }] },
  { key: "coated", name: "Au", bare: false,
    steps: [select("#model", "spectral"), input("#preset", "Au"), input("#name", "Au"), { selector: "#coated", checked: true },
            input("#coat-ior", "1.6"), input("#coat-roughness", "0.12"), input("#coat-color", "#f4e8c8"),
            input("#coat-weight", "0.85")], lights,
    refusals: [{ key: "coat index", steps: [input("#coat-ior", "1.01")], restore: [input("#coat-ior", "1.6")],
                 messageSelector: ".message[data-for='coat.ior']", control: "#coat-ior", phrase: "coat.ior: 1.01" }] },
  // A measured metal under a thin film (its own table in the render; three.js's iridescence of the
  // same film beside it), the coat switched off first.
  { key: "filmed", name: "Ti_film", bare: true,
    steps: [{ selector: "#coated", checked: false }, input("#preset", "Ti"), input("#name", "Ti_film"),
            { selector: "#filmed", checked: true }, input("#film-ior", "2.3"), input("#film-thickness", "300"),
            input("#film-weight", "0.9")], lights,
    refusals: [{ key: "film thickness", steps: [input("#film-thickness", "5000")], restore: [input("#film-thickness", "300")],
                 messageSelector: ".message[data-for='film.thickness']", control: "#film-thickness",
                 phrase: "film.thickness: 5000 is out of range; a number in [0, 2000]" }] },
  { key: "pasted material file", name: "pasted_steel", bare: true,
    steps: [{ paste: JSON.stringify({ name: "pasted_steel", description: "pasted", roughness: 0.3,
                                      f82_tint: { f0: [0.56, 0.57, 0.58], tint: [0.9, 0.93, 1.0] } }) }],
    lights: ["environment", "point"],
    refusals: [{ key: "pasted broken JSON", steps: [{ paste: "{\"name\": \"x\",\n \"ior\": {\"n\": [1, 2" }],
                 messageSelector: ".message[data-for='document']", phrase: "pasted.json:2:" }] },
  // A MaterialX document of two metals (Standard Surface, OpenPBR), the second chosen; a document
  // whose end tag does not match is refused at the tag, as natively.
  { key: "pasted MaterialX document", name: "copper_openpbr", bare: true, choices: ["gold_standard_surface", "copper_openpbr"],
    steps: [{ paste: kMaterialX }, select("#choice", "1")], lights: ["environment", "point"],
    refusals: [{ key: "pasted MaterialX with a wrong end tag",
                 steps: [{ paste: kMaterialX.replace("</open_pbr_surface>", "</open_pbr>") }],
                 messageSelector: ".message[data-for='document']",
                 phrase: "pasted.mtlx:16:5: error: malformed XML: Start-end tags mismatch" }] },
  // A glTF asset of two metals and a non-metal: the page offers its metals, the second chosen.
  { key: "pasted glTF asset", name: "Trim", bare: true, choices: ["Paint", "Trim"],
    steps: [{ paste: JSON.stringify({ asset: { version: "2.0" }, materials: [
      { name: "Paint", pbrMetallicRoughness: { baseColorFactor: [0.6, 0.05, 0.04, 1], roughnessFactor: 0.3 },
        extensions: { KHR_materials_clearcoat: { clearcoatFactor: 1 } } },
      { name: "Rubber", pbrMetallicRoughness: { metallicFactor: 0 } },
      { name: "Trim", pbrMetallicRoughness: { baseColorFactor: [0.55, 0.556, 0.554, 1], roughnessFactor: 0.3 } }] }) },
            select("#choice", "1")],
    lights: ["environment", "point"] },
  // A .gltf dropped with the buffer it names beside it: read together (the page has no folder).
  { key: "dropped glTF and its buffer", name: "Dropped_Chrome", bare: true,
    steps: [{ drop: [{ name: "trim.bin", text: "abcd" },
                     { name: "trim.gltf", text: JSON.stringify({ asset: { version: "2.0" },
                       buffers: [{ byteLength: 4, uri: "trim.bin" }],
                       materials: [{ name: "Dropped Chrome", pbrMetallicRoughness: {
                         baseColorFactor: [0.55, 0.556, 0.554, 1], roughnessFactor: 0.3 } }] }) }] }],
    lights: ["environment"] },
];

// metal_rough.glb's materials (gltf-assets.mjs): metalness 0, 128/255 and 1 from a texture, 0.3
// from a factor, and a plain full metal.
const kAssetMaterials = [...Object.keys(kMetalRough.textured), ...Object.keys(kMetalRough.factor), kMetalRough.plain];

const kConfig = { probeSize: kProbeSize, pixels: kProbePixels, point: kPointLight, rect: kProbeRectLight,
                  cases: kCases };

function pageSize() {
  let bytes = 0;
  for (const file of readdirSync(join(npmDir, "lookdev"))) bytes += statSync(join(npmDir, "lookdev", file)).size;
  return bytes;
}

// The largest difference between two JSON texts' numbers (relative above 1), and whether
// everything else (keys, strings, layout of values) is equal.
function jsonDifference(a, b) {
  let sameShape = true, worst = 0;
  const walk = (x, y) => {
    if (typeof x === "number" && typeof y === "number") {
      worst = Math.max(worst, Math.abs(x - y) / Math.max(1, Math.abs(y)));
    } else if (x && y && typeof x === "object" && typeof y === "object") {
      const keys = Object.keys(x);
      if (Array.isArray(x) !== Array.isArray(y) || keys.join() !== Object.keys(y).join()) sameShape = false;
      else for (const key of keys) walk(x[key], y[key]);
    } else if (x !== y) {
      sameShape = false;
    }
  };
  walk(JSON.parse(a), JSON.parse(b));
  return { sameShape, worst };
}

function maxDifference(a, b) {
  let worst = 0;
  a.forEach((value, i) => { worst = Math.max(worst, Math.abs(value - b[i])); });
  return a.length === b.length ? worst : Infinity;
}

const dir = mkdtempSync(join(tmpdir(), "matc-lookdev-"));
try {
  const metalRoughGlb = join(dir, "metal_rough.glb");
  await metalRoughAsset(metalRoughGlb);
  kCases.push({
    key: "dropped textured-metalness asset", name: "Metal_0", bare: true, lights: ["environment"],
    steps: [{ drop: [{ name: "metal_rough.glb", base64: readFileSync(metalRoughGlb).toString("base64") }] }],
    assetMaterials: kAssetMaterials, choices: kAssetMaterials.map((name) => name.replace(" ", "_")),
  });
  // On the wall clock: the dropped asset's textures decode off the page's thread, which virtual
  // time does not wait for (under load it ran out before they were read).
  const result = await runLookdevPage({ npmDir, config: kConfig, dir: join(dir, "page"), windowSize: kWindowSize,
                                        realTime: true, budgetMs: 240000 });
  check(result.errors.length === 0, `page: ${result.errors.join("\n")}`);
  check(result.console.length === 0, `the page's console: ${result.console.join("\n")}`);
  check(result.start?.name === "Cu", `the page started with ${result.start?.name}, not its default Cu`);

  const materials = join(dir, "materials");
  mkdirSync(materials);
  let worstCurve = 0, worstJson = 0, identicalSnippets = 0, identicalJson = 0;
  const renders = {};
  for (const testCase of kCases) {
    const shown = result.cases[testCase.key];
    check(Boolean(shown), `${testCase.key}: not run`);
    if (!shown) continue;
    check(!shown.refused && shown.messages.length === 0,
          `${testCase.key}: the page refused it: ${shown.status} ${shown.messages.join(" | ")}`);
    if (testCase.choices) {
      check(shown.choices.join() === testCase.choices.join(), `${testCase.key}: the page offers ${shown.choices}`);
    }
    // The exported material file, compiled by the native matc as a person would.
    const file = join(materials, `${testCase.name}.json`);
    writeFileSync(file, shown.exports.material);
    const out = join(dir, "out", testCase.key.replaceAll(" ", "_"));
    run(matc, ["-q", "-o", out, "--emit", "glsl,hlsl,wgsl,json", ...(testCase.colorSpace ? ["--color-space", testCase.colorSpace] : []), file]);
    for (const language of ["glsl", "wgsl", "hlsl"]) {
      const written = readFileSync(join(out, `${testCase.name}.${language}`), "utf8");
      check(shown.exports[language] === written, `${testCase.key}: the page's ${language} differs from matc's ${testCase.name}.${language}`);
      if (shown.exports[language] === written) identicalSnippets += 1;
    }
    const json = readFileSync(join(out, `${testCase.name}.json`), "utf8");
    const difference = jsonDifference(shown.exports.json, json);
    check(difference.sameShape && difference.worst <= 1e-12,
          `${testCase.key}: the page's coefficients differ from matc's ${testCase.name}.json (${difference.worst})`);
    worstJson = Math.max(worstJson, difference.worst);
    if (shown.exports.json === json) identicalJson += 1;

    // The plotted curves against the native library.
    const { mu } = shown.series;
    // f32: a filmed metal's F is its table's, which the page's library holds at f32.
    const evaluated = JSON.parse(run(matc, ["eval", file, "--lut-precision", "f32", "--mu", mu.join(","),
                                            ...(testCase.colorSpace ? ["--color-space", testCase.colorSpace] : [])]));
    const native = JSON.parse(execFileSync(apiDump, {
      input: `${JSON.stringify({ text: shown.exports.material, path: `${testCase.name}.json`, mu,
                                 options: { colorSpace: testCase.colorSpace ?? "" } })}\n`, encoding: "utf8" })).materials[0];
    for (const [plotted, reference, what] of [
      [shown.series.ours, evaluated.F.flat(), "F (matc eval)"], [shown.series.exact, evaluated.F_exact.flat(), "F_exact (matc eval)"],
      [shown.series.schlick, native.schlick, "Schlick"], [shown.series.f82Tint, native.f82_tint, "F82-tint"]]) {
      const worst = maxDifference(plotted, reference);
      check(worst <= 1e-12, `${testCase.key}: plotted ${what} differs by ${worst}`);
      worstCurve = Math.max(worstCurve, worst);
    }

    for (const [light, pixels] of Object.entries(shown.renders)) renders[`${testCase.name} ${light} r=0.3`] = pixels;
    // The asset view's full metal (matc's loader) is the chosen material's metal at metalness 1.
    for (const [light, pixels] of Object.entries(shown.asset?.renders?.["matc Metal Full"] ?? {})) {
      renders[`Metal_Full ${light} r=0.3`] = pixels;
    }
    for (const refusal of testCase.refusals ?? []) {
      const refused = result.refusals[refusal.key];
      check(Boolean(refused), `${refusal.key}: not run`);
      if (!refused) continue;
      check(refused.message.includes(refusal.phrase), `${refusal.key}: the message "${refused.message}" lacks "${refusal.phrase}"`);
      check(!/[\u0000-\u0008\u000b-\u001f\u007f]/.test(refused.message), `${refusal.key}: a control byte in the message`);
      check(refused.refused, `${refusal.key}: the status does not say refused`);
      check(refused.kept, `${refusal.key}: the last good material was not kept`);
      if (refusal.control) check(refused.controlMarked, `${refusal.key}: the control is not marked`);
    }
  }
  // The asset view of the dropped .glb.
  const assetCase = result.cases["dropped textured-metalness asset"];
  const asset = assetCase?.asset;
  const mixed = (asset?.metals ?? []).filter((metal) => metal.metalRough).map((metal) => metal.name);
  check(asset?.scene === "asset", `the dropped asset is not shown (scene ${asset?.scene})`);
  check(mixed.join() === [...Object.keys(kMetalRough.textured), ...Object.keys(kMetalRough.factor)].join(),
        `the asset's metals mixed per pixel: ${mixed}`);
  check(asset?.summary?.includes("4 mixed per pixel"), `the asset's line: ${asset?.summary}`);
  const assetRender = (load, name, light) => asset?.renders?.[`${load} ${name}`]?.[light] ?? [];
  const difference = (a, b) => (a.length === b.length && a.length > 0
    ? Math.max(...a.flatMap((rgb, i) => rgb.map((value, c) => Math.abs(value - b[i][c]) / Math.max(1, Math.abs(b[i][c])))))
    : Infinity);
  let worstAssetMix = 0;
  for (const light of assetCase ? ["environment"] : []) {
    const dielectric = assetRender("engine", "Metal 0", light), metal = assetRender("matc", "Metal Full", light);
    for (const [name, m] of [["Metal 0", 0], ["Metal Half", kMetalRough.textured["Metal Half"] / 255], ["Metal Full", 1],
                             ["Metal Factor", kMetalRough.factor["Metal Factor"]]]) {
      const d = difference(assetRender("matc", name, light), dielectric.map((rgb, i) => rgb.map((v, c) => (1 - m) * v + m * metal[i][c])));
      worstAssetMix = Math.max(worstAssetMix, d);
      check(d <= 1e-5, `the asset view's ${name}, ${light}: ${d} from (1 - ${m}) three.js's own + ${m} matc's metal`);
    }
    // That the view draws matc's metals, not three.js's own, is the `mixed` check above (matc's
    // define on each): a glTF metal is Schlick's curve, which a default build compiles exactly
    // (the f82 basis), so the two metals' renders may now agree.
  }
  const coated = result.cases.coated;
  check(coated?.labels?.[1]?.includes("F0 in coat"), `coated: the comparison's label ${coated?.labels}`);
  const filmed = result.cases.filmed;
  check(filmed?.labels?.[1]?.includes("iridescence"), `filmed: the comparison's label ${filmed?.labels}`);

  // The probes, each case under its lights, against the CPU runtime at the page's compile (linear Rec.709).
  // The asset view's full metal: the material file `matc import` writes for it.
  const imported = join(dir, "imported");
  run(matc, ["import", "-q", "-o", imported, metalRoughGlb]);
  writeFileSync(join(materials, "Metal_Full.json"), readFileSync(join(imported, "Metal_Full.json")));
  const assetProbes = assetCase ? [{ key: "Metal_Full environment r=0.3", light: "environment", roughness: 0.3 }] : [];
  const probeOut = join(dir, "probe-out");
  run(matc, ["-q", "-o", probeOut, "--emit", "json", ...kCases.map((c) => join(materials, `${c.name}.json`)),
             join(materials, "Metal_Full.json")]);
  const probeRenders = [...kCases.flatMap((c) => c.lights.map((light) => ({ key: `${c.name} ${light} r=0.3`, light, roughness: 0.3 }))),
                        ...assetProbes];
  const expected = expectedProbes({
    matc, materialsDir: materials, out: probeOut, ...kThreeJsProbeTerms, renders: probeRenders,
    bare: [...kCases.filter((c) => c.bare).map((c) => c.name), "Metal_Full"],
    coated: kCases.filter((c) => !c.bare).map((c) => c.name) });
  check(Object.keys(expected).length === probeRenders.length, `${Object.keys(expected).length} probe renders expected`);
  const worstProbe = compareProbes(renders, expected);

  // The link: the coated case's URL, opened afresh, shows the same material.
  const again = await runLookdevPage({ npmDir, config: { cases: [] }, dir: join(dir, "link"), windowSize: kWindowSize,
                                       fragment: coated?.hash ?? "" });
  check(again.errors.length === 0 && again.console.length === 0, `the link: ${[...again.errors, ...again.console].join("\n")}`);
  check(again.start?.exports?.glsl === coated?.exports?.glsl, "the coated case's link does not reproduce its GLSL");

  // A broken link: the default metal, the reason beside the document box, the text not run as markup.
  const broken = await runLookdevPage({ npmDir, config: { cases: [] }, dir: join(dir, "broken-link"), windowSize: kWindowSize,
                                        fragment: "#material=%7B%3Cimg%20src%3Dx%20onerror%3Dalert(1)%3E&view=%3Cb%3E" });
  check(broken.errors.length === 0 && broken.console.length === 0, `a broken link: ${[...broken.errors, ...broken.console].join("\n")}`);
  check(broken.start?.name === "Cu", `a broken link opened ${broken.start?.name}, not the default Cu`);
  check(broken.start?.documentMessage === "the link's material is not JSON",
        `a broken link's message: ${broken.start?.documentMessage}`);

  const size = pageSize();
  check(size <= kSizeLimit, `the page and its assets: ${size} bytes, over ${kSizeLimit}`);
  console.log(`look-development page: ${kCases.length} materials through its controls, ${probeRenders.length} ` +
              `renders x ${kProbePixels.length} probes, largest difference from the CPU runtime ` +
              `${worstProbe.toExponential(2)}; curves within ${worstCurve.toExponential(2)} of the native library; ` +
              `${identicalSnippets} snippets byte-identical to matc's, ${identicalJson} of ${kCases.length} ` +
              `<name>.json too (the others within ${worstJson.toExponential(2)}); ` +
              `${Object.keys(result.refusals).length} refusals shown beside their controls; a dropped textured-metalness ` +
              `asset in the asset view within ${worstAssetMix.toExponential(2)} of the mix of three.js's own and matc's metal; the link reproduces ` +
              `a coated material; page ${(size / 1024).toFixed(1)} KiB`);
} finally {
  rmSync(dir, { recursive: true, force: true });
}
finish();
