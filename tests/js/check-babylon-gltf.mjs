// The Babylon.js glTF loader extension (js/package/babylon/matc-gltf.mjs): the car asset built with
// glTF-Transform (gltf-assets.mjs: a textured car paint under a clear coat, a chrome, a rubber
// tyre, an iridescent foil, a textured trim of Schlick's curve and an edge-coloured one) loaded by Babylon's own glTF loader (@babylonjs/loaders) in headless Chromium
// three ways, as check-three-gltf.mjs loads it in three.js (gltf-loader-checks.mjs: compiled in
// the page; as `matc gltf` wrote it with no compiler; the same with a build directory of the
// asset), with the same checks: which materials became matc metals and from where, the warnings,
// and the probes against the CPU runtime, to 1e-4.
//   node check-babylon-gltf.mjs MATC NPM_DIR
import { modulePage } from "./browser-page.mjs";
import { kBabylonProbeTerms, kProbeSize } from "./engine-probes.mjs";
import { runLoaderCheck } from "./gltf-loader-checks.mjs";

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
        material.metadata?.matc ? (material.matcFresnel.kind === "schlick" ? "per-pixel" :
                                   (material.matcFresnel.kind === "f0Table" ? "f0-table " : "") +
                                   (material.matcFresnel.coat ? "coated" : material.matcFresnel.film ? "filmed" : "bare")) +
                                  " " + material.metadata.matc.from +
                                  (/from MATC_materials_fresnel/.test(material.matcFresnel.coat?.snippet) ? " (template)" : "")
                                : "engine"]));
      return { byName, kinds, made: registration.materials.length };
    } finally {
      registration.unregister();
    }
  };
  const loads = {};
  for (const [name, url, options] of [["compiled", "/assets/car.glb", { matc, build }],
                                      ["extension", "/assets/car_matc.glb", { build }],
                                      ["directory", "/assets/car_matc.glb", { build: await loadMatcBuild("/build/", scene) }]]) {
    out.console.push("-- " + name);
    loads[name] = await load(url, options);
  }
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

await runLoaderCheck({
  engine: "Babylon.js", page, terms: kBabylonProbeTerms,
  summary: (worst) => `Babylon.js's glTF loader with matc's extension: a glTF-Transform car asset's paint (coated), ` +
              `chrome and trims (textured, per pixel) became matc metals compiled in the page, the iridescent foil a filmed matc metal (its own table), the lacquered foil a coated one (its table the base lobe), the tyre kept Babylon's material, largest difference from the CPU runtime ` +
              `${worst.compiled.toExponential(2)}; from matc gltf's asset without the compiler, every metal took ` +
              `MATC_materials_fresnel's coefficients (the foils their films' tables), the coated paint its snippet from matc's template ` +
              `(${worst.extension.toExponential(2)}); with a build directory of the asset, the paint took its snippet ` +
              `from it (${worst.directory.toExponential(2)})`,
}, process.argv.slice(2));
