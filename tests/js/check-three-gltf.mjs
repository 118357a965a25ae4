// The three.js GLTFLoader plugin (js/package/three/matc-gltf.mjs): a car asset built with
// glTF-Transform (gltf-assets.mjs: a car paint under a clear coat, a chrome, a rubber tyre, an
// iridescent foil) loaded by three.js's own GLTFLoader in headless Chromium with the plugin and
// the package's in-page compiler. The paint and the chrome must become matc metals (the paint a
// coated one), the tyre and the foil keep three.js's material (the foil with a console warning
// that says why); the loaded paint's and chrome's materials, on the probe plane under the engine
// checks' lights, equal the CPU runtime's prediction for the material files `matc import` writes
// from the same asset, to 1e-4. Then the same asset written by `matc gltf` (MATC_materials_fresnel
// in each metal), loaded with the plugin and no compiler in the page: the chrome takes its
// coefficients from the extension (and renders as the compiled one does), the coated paint keeps
// three.js's material with a warning that it needs the compiler.
//   node check-three-gltf.mjs MATC NPM_DIR
import { mkdtempSync, rmSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { kWebRoots, modulePage, runPage } from "./browser-page.mjs";
import { compareProbes, expectedProbes, kPointLight, kProbePixels, kProbeRectLight, kProbeSize,
         kThreeJsProbeTerms } from "./engine-probes.mjs";
import { carAssetsForLoaders } from "./gltf-assets.mjs";
import { check, finish } from "./report.mjs";
import { run } from "./shader-cases.mjs";

const [matc, npmDir] = process.argv.slice(2);
const kLights = ["environment", "point", "rect"];
// three.js's material name -> the matc material `matc import` writes for it.
const kProbed = { "Car Paint": "Car_Paint", Chrome: "Chrome" };

const page = (config) => modulePage(config, {
  head: `import * as THREE from "three";
import { GLTFLoader } from "three/addons/loaders/GLTFLoader.js";
import { RectAreaLightUniformsLib } from "three/addons/lights/RectAreaLightUniformsLib.js";
import { createMatc } from "/web/index.mjs";
import { compiledMatcBuildFiles } from "/web/matc-build.mjs";
import { loadMatcBuild } from "/web/three/matc-three.mjs";
import { matcGltfPlugin } from "/web/three/matc-gltf.mjs";
import { probeScene, probeSetup, renderProbePixels } from "/checks/three-scene-page.mjs";
`,
  body: `
  out.console = [];
  for (const level of ["error", "warn"]) {
    const original = console[level].bind(console);
    console[level] = (...args) => { out.console.push(level + ": " + args.join(" ")); original(...args); };
  }
  const renderer = new THREE.WebGLRenderer({ canvas: document.createElement("canvas") });
  RectAreaLightUniformsLib.init();
  const matc = await createMatc();
  const build = await loadMatcBuild(await compiledMatcBuildFiles(matc));
  const load = async (url, plugin) => {
    const gltf = await new GLTFLoader().register(plugin).loadAsync(url);
    const byName = {};
    gltf.scene.traverse((object) => { if (object.isMesh) byName[object.material.name] = object.material; });
    const kinds = Object.fromEntries(Object.entries(byName).map(([name, material]) =>
      [name, material.userData.matc ? (material.userData.matc.source.material.coat ? "coated" : "bare") +
                                      " " + material.userData.matc.from : "three"]));
    return { byName, kinds };
  };
  const { byName, kinds } = await load("/assets/car.glb", matcGltfPlugin({ matc, build }));
  out.matc = kinds;
  // The asset written by matc gltf, with no compiler given to the plugin.
  out.console.push("-- without the compiler");
  const written = await load("/assets/car_matc.glb", matcGltfPlugin({ build }));
  out.matcWithoutCompiler = written.kinds;
  const { target, camera, environment } = probeSetup(THREE, renderer, ${kProbeSize});
  out.renders = {};
  out.extensionRenders = {};
  for (const [name, key] of Object.entries(config.probed)) {
    for (const light of config.lights) {
      out.renders[key + " " + light + " r=0.3"] = renderProbePixels(
          renderer, probeScene(THREE, byName[name], light, config, environment), camera, target, config.pixels);
    }
  }
  for (const light of config.lights) {
    out.extensionRenders[config.fromExtension + " " + light + " r=0.3"] = renderProbePixels(renderer,
        probeScene(THREE, written.byName[config.fromExtension], light, config, environment), camera, target, config.pixels);
  }
`,
});

const dir = mkdtempSync(join(tmpdir(), "matc-three-gltf-"));
try {
  const { assets, car } = await carAssetsForLoaders(dir, matc);
  const result = await runPage({
    html: page({ probed: kProbed, lights: kLights, pixels: kProbePixels, point: kPointLight, rect: kProbeRectLight,
                 fromExtension: "Chrome" }),
    roots: { ...kWebRoots, web: npmDir, assets }, dir });
  check(result.errors.length === 0, `page: ${result.errors.join("\n")}`);
  const expectedKinds = { "Car Paint": "coated compiled", Chrome: "bare compiled", Tyre: "three", Foil: "three" };
  for (const [name, kind] of Object.entries(expectedKinds)) {
    check(result.matc?.[name] === kind, `${name}: ${result.matc?.[name]}, not ${kind}`);
  }
  const withoutCompiler = { "Car Paint": "three", Chrome: "bare extension", Tyre: "three", Foil: "three" };
  for (const [name, kind] of Object.entries(withoutCompiler)) {
    check(result.matcWithoutCompiler?.[name] === kind,
          `${name} without the compiler: ${result.matcWithoutCompiler?.[name]}, not ${kind}`);
  }
  const lines = result.console ?? [];
  const split = lines.indexOf("-- without the compiler");
  const [warnings, laterWarnings] = [lines.slice(0, split), lines.slice(split + 1).filter((line) => line.startsWith("warn:"))];
  check(warnings.some((line) => /glTF materials\[3\] "Foil" keeps three.js's Fresnel: matc: iridescence/.test(line)),
        `no warning for the iridescent foil: ${warnings.join("\n")}`);
  check(warnings.every((line) => /Foil|iridescence/.test(line)), `unexpected console output: ${warnings.join("\n")}`);
  check(laterWarnings.length === 2 &&
        laterWarnings.some((line) => /materials\[0\] "Car Paint" keeps three.js's Fresnel: matc: a coated metal: its shader snippet comes from the compiler/.test(line)) &&
        laterWarnings.some((line) => /materials\[3\] "Foil" keeps three.js's Fresnel: matc: iridescence/.test(line)),
        `warnings without the compiler: ${laterWarnings.join("\n")}`);

  // The CPU runtime's prediction for the material files matc import writes from the same asset.
  const materials = join(dir, "materials");
  run(matc, ["import", "-q", "-o", materials, car]);
  const out = join(dir, "out");
  run(matc, ["-q", "-o", out, "--emit", "json", ...Object.values(kProbed).map((name) => join(materials, `${name}.json`))]);
  const renders = Object.values(kProbed).flatMap((name) => kLights.map((light) => ({ key: `${name} ${light} r=0.3`, light })));
  const expected = expectedProbes({
    matc, materialsDir: materials, out, ...kThreeJsProbeTerms, renders,
    bare: ["Chrome"], coated: ["Car_Paint"] });
  check(Object.keys(expected).length === renders.length, `${Object.keys(expected).length} renders expected`);
  const worst = compareProbes(result.renders ?? {}, expected);
  const fromExtension = Object.fromEntries(kLights.map((light) => [`Chrome ${light} r=0.3`, expected[`Chrome ${light} r=0.3`]]));
  const worstFromExtension = compareProbes(result.extensionRenders ?? {}, fromExtension);
  console.log(`three.js GLTFLoader with matc's plugin: a glTF-Transform car asset's paint (coated) and chrome ` +
              `became matc metals, the tyre and the iridescent foil kept three.js's material (the foil with ` +
              `a warning); ${renders.length} renders x ${kProbePixels.length} probes, largest difference from ` +
              `the CPU runtime ${worst.toExponential(2)}; from matc gltf's asset without the compiler, the chrome ` +
              `took MATC_materials_fresnel's coefficients (${kLights.length} renders, largest difference ` +
              `${worstFromExtension.toExponential(2)}) and the coated paint kept three.js's material with a warning`);
} finally {
  rmSync(dir, { recursive: true, force: true });
}
finish();
