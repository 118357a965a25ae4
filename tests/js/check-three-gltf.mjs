// The three.js GLTFLoader plugin (js/package/three/matc-gltf.mjs): a car asset built with
// glTF-Transform (gltf-assets.mjs: a car paint under a clear coat, a chrome, a rubber tyre, an
// iridescent foil) loaded by three.js's own GLTFLoader in headless Chromium with the plugin and
// the package's in-page compiler. The paint and the chrome must become matc metals (the paint a
// coated one), the tyre and the foil keep three.js's material (the foil with a console warning
// that says why); the loaded paint's and chrome's materials, on the probe plane under the engine
// checks' lights, equal the CPU runtime's prediction for the material files `matc import` writes
// from the same asset, to 1e-4.
//   node check-three-gltf.mjs MATC NPM_DIR
import { mkdirSync, mkdtempSync, rmSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { kWebRoots, modulePage, runPage } from "./browser-page.mjs";
import { compareProbes, expectedProbes, kPointLight, kProbePixels, kProbeRectLight, kProbeSize,
         kThreeJsProbeTerms } from "./engine-probes.mjs";
import { carAsset } from "./gltf-assets.mjs";
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
  const gltf = await new GLTFLoader().register(matcGltfPlugin({ matc, build })).loadAsync("/assets/car.glb");
  const byName = {};
  gltf.scene.traverse((object) => { if (object.isMesh) byName[object.material.name] = object.material; });
  out.matc = Object.fromEntries(Object.entries(byName).map(([name, material]) =>
    [name, material.userData.matc ? (material.userData.matc.source.material.coat ? "coated" : "bare") : "three"]));
  const { target, camera, environment } = probeSetup(THREE, renderer, ${kProbeSize});
  out.renders = {};
  for (const [name, key] of Object.entries(config.probed)) {
    for (const light of config.lights) {
      out.renders[key + " " + light + " r=0.3"] = renderProbePixels(
          renderer, probeScene(THREE, byName[name], light, config, environment), camera, target, config.pixels);
    }
  }
`,
});

const dir = mkdtempSync(join(tmpdir(), "matc-three-gltf-"));
try {
  const assets = join(dir, "assets");
  mkdirSync(assets);
  const car = join(assets, "car.glb");
  await carAsset(car, { paintRoughness: 0.3, chromeRoughness: 0.3, foil: true });
  const result = await runPage({
    html: page({ probed: kProbed, lights: kLights, pixels: kProbePixels, point: kPointLight, rect: kProbeRectLight }),
    roots: { ...kWebRoots, web: npmDir, assets }, dir });
  check(result.errors.length === 0, `page: ${result.errors.join("\n")}`);
  const expectedKinds = { "Car Paint": "coated", Chrome: "bare", Tyre: "three", Foil: "three" };
  for (const [name, kind] of Object.entries(expectedKinds)) {
    check(result.matc?.[name] === kind, `${name}: ${result.matc?.[name]}, not ${kind}`);
  }
  const warnings = result.console ?? [];
  check(warnings.some((line) => /glTF materials\[3\] "Foil" keeps three.js's Fresnel: matc: iridescence/.test(line)),
        `no warning for the iridescent foil: ${warnings.join("\n")}`);
  check(warnings.every((line) => /Foil|iridescence/.test(line)), `unexpected console output: ${warnings.join("\n")}`);

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
  console.log(`three.js GLTFLoader with matc's plugin: a glTF-Transform car asset's paint (coated) and chrome ` +
              `became matc metals, the tyre and the iridescent foil kept three.js's material (the foil with ` +
              `a warning); ${renders.length} renders x ${kProbePixels.length} probes, largest difference from ` +
              `the CPU runtime ${worst.toExponential(2)}`);
} finally {
  rmSync(dir, { recursive: true, force: true });
}
finish();
