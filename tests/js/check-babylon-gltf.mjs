// The Babylon.js glTF loader extension (js/package/babylon/matc-gltf.mjs): the car asset built with
// glTF-Transform (gltf-assets.mjs: a car paint under a clear coat, a chrome, a rubber tyre, an
// iridescent foil) loaded by Babylon's own glTF loader (@babylonjs/loaders) in headless Chromium,
// first with the package's in-page compiler, then as `matc gltf` wrote it (MATC_materials_fresnel
// in each metal) with no compiler. Compiled: the paint and the chrome become matc metals (the
// paint a coated one), the tyre and the foil keep Babylon's material (the foil with a console
// warning that says why). From the extension: the chrome takes its coefficients from it, the
// coated paint keeps Babylon's material with a warning that it needs the compiler. The loaded
// materials, on the probe plane under the engine checks' lights, equal the CPU runtime's
// prediction for the material files `matc import` writes from the same asset, to 1e-4.
//   node check-babylon-gltf.mjs MATC NPM_DIR
import { mkdtempSync, rmSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { kWebRoots, modulePage, runPage } from "./browser-page.mjs";
import { compareProbes, expectedProbes, kBabylonProbeTerms, kPointLight, kProbePixels, kProbeRectLight,
         kProbeSize } from "./engine-probes.mjs";
import { carAssetsForLoaders } from "./gltf-assets.mjs";
import { check, finish } from "./report.mjs";
import { run } from "./shader-cases.mjs";

const [matc, npmDir] = process.argv.slice(2);
const kLights = ["environment", "point", "rect"];
// Babylon's material name -> the matc material `matc import` writes for it; renders of each load.
const kProbed = { compiled: { "Car Paint": "Car_Paint", Chrome: "Chrome" }, extension: { Chrome: "Chrome" } };

const page = (config) => modulePage(config, {
  head: `import "@babylonjs/loaders/glTF/2.0/index.js";
import { LoadAssetContainerAsync } from "@babylonjs/core/Loading/sceneLoader.js";
import { createMatc } from "/web/index.mjs";
import { compiledMatcBuildFiles } from "/web/matc-build.mjs";
import { loadMatcBuild } from "/web/babylon/matc-babylon.mjs";
import { registerMatcGltfExtension } from "/web/babylon/matc-gltf.mjs";
import { babylonProbeScene, renderBabylonProbe } from "/checks/babylon-scene-page.mjs";
`,
  body: `
  out.console = [];
  for (const level of ["error", "warn"]) {
    const original = console[level].bind(console);
    console[level] = (...args) => { out.console.push(level + ": " + args.join(" ")); original(...args); };
  }
  const { scene, camera } = babylonProbeScene(${kProbeSize});
  const matc = await createMatc();
  const build = await loadMatcBuild(await compiledMatcBuildFiles(matc), scene);
  const load = async (url, options) => {
    const registration = registerMatcGltfExtension(options);
    try {
      const container = await LoadAssetContainerAsync(url, scene);
      const byName = Object.fromEntries(container.materials.map((material) => [material.name, material]));
      const kinds = Object.fromEntries(container.materials.map((material) => [material.name,
        material.metadata?.matc ? (material.matcFresnel.coat ? "coated" : "bare") + " " + material.metadata.matc.from
                                : "babylon"]));
      return { byName, kinds, made: registration.materials.length };
    } finally {
      registration.unregister();
    }
  };
  const loads = { compiled: await load("/assets/car.glb", { matc, build }) };
  out.console.push("-- without the compiler");
  loads.extension = await load("/assets/car_matc.glb", { build });
  out.kinds = Object.fromEntries(Object.entries(loads).map(([name, load]) => [name, load.kinds]));
  out.made = Object.fromEntries(Object.entries(loads).map(([name, load]) => [name, load.made]));
  out.renders = {};
  for (const [load, probed] of Object.entries(config.probed)) {
    for (const [name, key] of Object.entries(probed)) {
      for (const light of config.lights) {
        const renderKey = load + " " + key + " " + light + " r=0.3";
        out.renders[renderKey] = await renderBabylonProbe({ scene, camera, material: loads[load].byName[name], light,
                                                            config, size: ${kProbeSize}, out, key: renderKey });
      }
    }
  }
`,
});

const dir = mkdtempSync(join(tmpdir(), "matc-babylon-gltf-"));
try {
  const { assets, car } = await carAssetsForLoaders(dir, matc);
  const result = await runPage({
    html: page({ probed: kProbed, lights: kLights, pixels: kProbePixels, point: kPointLight, rect: kProbeRectLight }),
    roots: { ...kWebRoots, web: npmDir, assets }, dir });
  check(result.errors.length === 0, `page: ${result.errors.join("\n")}`);
  const expectedKinds = {
    compiled: { "Car Paint": "coated compiled", Chrome: "bare compiled", Tyre: "babylon", Foil: "babylon" },
    extension: { "Car Paint": "babylon", Chrome: "bare extension", Tyre: "babylon", Foil: "babylon" },
  };
  for (const [load, kinds] of Object.entries(expectedKinds)) {
    for (const [name, kind] of Object.entries(kinds)) {
      check(result.kinds?.[load]?.[name] === kind, `${load}: ${name}: ${result.kinds?.[load]?.[name]}, not ${kind}`);
    }
  }
  check(result.made?.compiled === 2 && result.made?.extension === 1, `materials made: ${JSON.stringify(result.made)}`);
  const lines = result.console ?? [];
  const split = lines.indexOf("-- without the compiler");
  const warnings = (from, to) => lines.slice(from, to).filter((line) => line.startsWith("warn:"));
  const [first, second] = [warnings(0, split), warnings(split + 1)];
  const foil = /glTF materials\[3\] "Foil" keeps Babylon.js's Fresnel: matc: iridescence/;
  check(first.length === 1 && foil.test(first[0]), `warnings with the compiler: ${first.join("\n")}`);
  check(second.length === 2 && second.some((line) => foil.test(line)) &&
        second.some((line) => /materials\[0\] "Car Paint" keeps Babylon.js's Fresnel: matc: a coated metal: its shader snippet comes from the compiler/.test(line)),
        `warnings without the compiler: ${second.join("\n")}`);

  // The CPU runtime's prediction for the material files matc import writes from the same asset.
  const materials = join(dir, "materials");
  run(matc, ["import", "-q", "-o", materials, car]);
  const out = join(dir, "out");
  run(matc, ["-q", "-o", out, "--emit", "json", ...["Car_Paint", "Chrome"].map((name) => join(materials, `${name}.json`))]);
  const renders = ["Car_Paint", "Chrome"].flatMap((name) => kLights.map((light) => ({ key: `${name} ${light} r=0.3`, light })));
  const expected = expectedProbes({ matc, materialsDir: materials, out, ...kBabylonProbeTerms, renders,
                                    bare: ["Chrome"], coated: ["Car_Paint"] });
  check(Object.keys(expected).length === renders.length, `${Object.keys(expected).length} renders expected`);
  const worst = {};
  for (const [load, probed] of Object.entries(kProbed)) {
    const keys = Object.values(probed).flatMap((name) => kLights.map((light) => `${name} ${light} r=0.3`));
    worst[load] = compareProbes(Object.fromEntries(keys.map((key) => [key, result.renders?.[`${load} ${key}`]])),
                                Object.fromEntries(keys.map((key) => [key, expected[key]])));
  }
  console.log(`Babylon.js's glTF loader with matc's extension: a glTF-Transform car asset's paint (coated) and ` +
              `chrome became matc metals compiled in the page, the tyre and the iridescent foil kept Babylon's ` +
              `material (the foil with a warning), largest difference from the CPU runtime ` +
              `${worst.compiled.toExponential(2)}; from matc gltf's asset without the compiler, the chrome took ` +
              `MATC_materials_fresnel's coefficients (${worst.extension.toExponential(2)}) and the coated paint kept ` +
              `Babylon's material with a warning`);
} finally {
  rmSync(dir, { recursive: true, force: true });
}
finish();
