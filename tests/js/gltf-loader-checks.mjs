// What the engines' glTF loader checks share (check-three-gltf.mjs, check-babylon-gltf.mjs): the
// car asset (with textured metals followed per pixel: a bare trim of Schlick's curve, an
// edge-coloured trim and the coated paint from their F0 tables) three ways (compiled in the page; as `matc gltf` wrote it, with no compiler; the same
// with a build directory that compiled the asset) and the checks of what each load made: which
// materials became matc metals and from where, the console warnings, and the probes against the
// CPU runtime's prediction for the material files `matc import` writes from the same asset.
import { mkdirSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { kWebRoots, runPage } from "./browser-page.mjs";
import { compareProbes, expectedProbes, kPointLight, kProbePixels, kProbeRectLight, kProbeSize } from "./engine-probes.mjs";
import { carAsset } from "./gltf-assets.mjs";
import { check, finish } from "./report.mjs";
import { run } from "./shader-cases.mjs";

// The module imports and first lines of a three.js (WebGLRenderer) glTF loader page
// (check-three-gltf.mjs, check-three-metal-rough.mjs): the console recorded, a renderer with rect
// lights, the compiler and its build in the page, and the probe target, camera and environment.
export const kThreeGltfPageHead = `import * as THREE from "three";
import { GLTFLoader } from "three/addons/loaders/GLTFLoader.js";
import { RectAreaLightUniformsLib } from "three/addons/lights/RectAreaLightUniformsLib.js";
import { createMatc } from "/web/index.mjs";
import { compiledMatcBuildFiles } from "/web/matc-build.mjs";
import { loadMatcBuild } from "/web/three/matc-three.mjs";
import { matcGltfPlugin } from "/web/three/matc-gltf.mjs";
import { loadCarThreeWays, recordConsole } from "/checks/three-gltf-loads-page.mjs";
import { probeScene, probeSetup, renderProbePixels } from "/checks/three-scene-page.mjs";
`;
export const kThreeGltfPageSetup = `
  recordConsole(out);
  const renderer = new THREE.WebGLRenderer({ canvas: document.createElement("canvas") });
  RectAreaLightUniformsLib.init();
  const matc = await createMatc();
  const build = await loadMatcBuild(await compiledMatcBuildFiles(matc));
  const { target, camera, environment } = probeSetup(THREE, renderer, ${kProbeSize});
`;

const kLights = ["environment", "point", "rect"];
// The engine's material name -> the matc material `matc import` writes for it, per load.
const kProbed = { compiled: { "Car Paint": "Car_Paint", Chrome: "Chrome", Trim: "Trim", "Edge Trim": "Edge_Trim", Foil: "Foil",
                              "Lacquered Foil": "Lacquered_Foil" },
                  extension: { "Car Paint": "Car_Paint", Chrome: "Chrome", Trim: "Trim", "Edge Trim": "Edge_Trim", Foil: "Foil",
                               "Lacquered Foil": "Lacquered_Foil" },
                  directory: { "Car Paint": "Car_Paint", Trim: "Trim", "Edge Trim": "Edge_Trim",
                               "Lacquered Foil": "Lacquered_Foil" } };
// The textured metals (gltf-assets.mjs, perPixel): their base colour per pixel is their factor times
// their texels (255, 0, 255), so the metal is the one `matc import` writes with green F0 0. The
// paint's and the edge trim's other channels sit on entries of their F0 tables, which hold the
// metal compiled there: what the CPU runtime predicts for these files, the loaders must draw
// (the interpolation between entries is checked against the CPU runtime on lavapipe, docs/gltf.md).
const kPerPixel = ["Car_Paint", "Trim", "Edge_Trim"];

// In `dir`: assets/car.glb (roughness 0.3, the foil), assets/car_matc.glb (`matc gltf`'s) and
// build/ (`matc -o build car.glb`: the metals' JSON and GLSL and WGSL snippets, the tables). Returns
// { assets, car, build }: the folders to serve and the asset.
async function carAssetsForLoaders(dir, matc) {
  const assets = join(dir, "assets");
  mkdirSync(assets);
  const car = join(assets, "car.glb");
  await carAsset(car, { paintRoughness: 0.3, chromeRoughness: 0.3, foil: true, airFoil: true, lacqueredFoil: true,
                        trim: true, perPixel: true });
  run(matc, ["gltf", "-q", car, "-o", join(assets, "car_matc.glb")]);
  const build = join(dir, "build");
  run(matc, ["-q", "-o", build, "--emit", "glsl,wgsl,json,lut,ltc", car]);
  return { assets, car, build };
}

// What each load must make: the materials' kinds ("coated compiled", "bare extension", "engine":
// the engine's own), how many became matc metals, and the warnings. The foil (KHR_materials_iridescence
// on a metal) is a filmed matc metal in place of the engine's iridescence, from its own table; the
// air foil (a film of index 1) a bare one in its place (with the engine's iridescence left on, the
// integrations would refuse it: a warning, and the engine's material). The lacquered foil (the
// same film under a clear coat) is a coated matc metal whose film table is its base lobe; from the
// extension alone, its snippet is the film-under-a-coat template's.
const kLoads = {
  compiled: { kinds: { "Car Paint": "f0-table coated compiled", Chrome: "bare compiled", Tyre: "engine", Foil: "filmed compiled",
                        "Air Foil": "bare compiled", "Lacquered Foil": "coated compiled", Trim: "per-pixel compiled",
                        "Edge Trim": "f0-table bare compiled" },
              made: 7, warnings: [] },
  extension: { kinds: { "Car Paint": "f0-table coated extension (template)", Chrome: "bare extension", Tyre: "engine",
                         Foil: "filmed extension", "Air Foil": "bare extension",
                         "Lacquered Foil": "coated extension (template)", Trim: "per-pixel extension",
                         "Edge Trim": "f0-table bare extension" },
               made: 7, warnings: [] },
  directory: { kinds: { "Car Paint": "f0-table coated extension", Chrome: "bare extension", Tyre: "engine", Foil: "filmed extension",
                         "Air Foil": "bare extension", "Lacquered Foil": "coated extension", Trim: "per-pixel extension",
                         "Edge Trim": "f0-table bare extension" },
               made: 7, warnings: [] },
};

// Checks a loader page's `result` ({ kinds, made, console: lines with "-- <load>" before each
// load's, renders: "<load> <matc name> <light> r=0.3" }); `engine` names the engine in its
// warnings, `terms` its probe terms (engine-probes.mjs). Returns the largest probe difference per
// load.
function loaderChecks({ result, engine, matc, car, dir, probed, lights, terms }) {
  const lines = result.console ?? [];
  for (const [load, expected] of Object.entries(kLoads)) {
    for (const [name, kind] of Object.entries(expected.kinds)) {
      check(result.kinds?.[load]?.[name] === kind, `${load}: ${name}: ${result.kinds?.[load]?.[name]}, not ${kind}`);
    }
    check(result.made?.[load] === expected.made, `${load}: ${result.made?.[load]} materials made matc metals`);
    const start = lines.indexOf(`-- ${load}`);
    const end = lines.findIndex((line, i) => i > start && line.startsWith("-- "));
    const warnings = lines.slice(start + 1, end < 0 ? lines.length : end).filter((line) => line.startsWith("warn:"));
    check(start >= 0 && warnings.length === expected.warnings.length &&
          expected.warnings.every((pattern) => warnings.some((line) => pattern.test(line))),
          `${load}: warnings: ${warnings.join("\n")}`);
  }
  // The CPU runtime's prediction for the material files matc import writes from the same asset.
  // The textured metals': their F0 per pixel, not the factor matc import writes.
  const materials = join(dir, "materials");
  run(matc, ["import", "-q", "-o", materials, car]);
  for (const name of kPerPixel) {
    const file = join(materials, `${name}.json`);
    const material = JSON.parse(readFileSync(file, "utf8"));
    material.f82_tint.f0[1] = 0;
    writeFileSync(file, JSON.stringify(material));
  }
  const out = join(dir, "out");
  const names = ["Car_Paint", "Chrome", "Trim", "Edge_Trim", "Foil", "Lacquered_Foil"];
  run(matc, ["-q", "-o", out, "--emit", "json", ...names.map((name) => join(materials, `${name}.json`))]);
  const renders = names.flatMap((name) => lights.map((light) => ({ key: `${name} ${light} r=0.3`, light })));
  const expected = expectedProbes({ matc, materialsDir: materials, out, ...terms, renders,
                                    bare: ["Chrome", "Trim", "Edge_Trim", "Foil"], coated: ["Car_Paint", "Lacquered_Foil"] });
  check(Object.keys(expected).length === renders.length, `${Object.keys(expected).length} renders expected`);
  const worst = {};
  for (const [load, names] of Object.entries(probed)) {
    const keys = Object.values(names).flatMap((name) => lights.map((light) => `${name} ${light} r=0.3`));
    worst[load] = compareProbes(Object.fromEntries(keys.map((key) => [key, result.renders?.[`${load} ${key}`]])),
                                Object.fromEntries(keys.map((key) => [key, expected[key]])));
  }
  return worst;
}

// An engine's loader check: its page (config -> HTML: { probed, lights, pixels, point, rect }; it
// loads /assets/car.glb and /assets/car_matc.glb, the latter also with /build/) run over the car
// assets in real time, then the checks above. `engine` names it in its warnings, `terms` are its
// probe terms; `summary(worst)` says what was measured; `browserArgs`, Chromium's flags (WebGPU's);
// `checkResult(result)`, the engine's own checks of what its page reported. argv: MATC NPM_DIR.
export async function runLoaderCheck({ engine, page, terms, summary, browserArgs = [], checkResult = () => {} },
                                     [matc, npmDir]) {
  const dir = mkdtempSync(join(tmpdir(), "matc-gltf-loader-"));
  try {
    const { assets, car, build } = await carAssetsForLoaders(dir, matc);
    const result = await runPage({
      html: page({ probed: kProbed, lights: kLights, pixels: kProbePixels, point: kPointLight, rect: kProbeRectLight }),
      // Real time: under virtual time Chromium may call the page done while it waits on a
      // texture's decode (no network fetch pending), before the third load has run.
      roots: { ...kWebRoots, web: npmDir, assets, build }, dir, realTime: true, budgetMs: 120000, browserArgs });
    check(result.errors.length === 0, `page: ${result.errors.join("\n")}`);
    checkResult(result);
    console.log(summary(loaderChecks({ result, engine, matc, car, dir, probed: kProbed, lights: kLights, terms })));
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
  finish();
}
