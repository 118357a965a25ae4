// The three.js GLTFLoader plugin (js/package/three/matc-gltf.mjs): a car asset built with
// glTF-Transform (gltf-assets.mjs: a textured car paint under a clear coat, a chrome, a rubber
// tyre, an iridescent foil, a textured trim of Schlick's curve and an edge-coloured one) loaded by three.js's own GLTFLoader in headless Chromium three ways:
//   - compiled: car.glb, with the package's in-page compiler: the paint, the chrome and the foil
//     become matc metals (the paint a coated one, the foil a filmed one in place of three.js's
//     iridescence), the tyre keeps three.js's material;
//   - extension: what `matc gltf` wrote from it (MATC_materials_fresnel in each metal), with no
//     compiler: every metal takes its coefficients from the extension (the foils their films' tables), the coated paint its
//     snippet from matc's template filled with the extension's values;
//   - directory: the same with a build directory that compiled the asset (`matc -o build car.glb`)
//     and no compiler: the paint becomes a coated metal too, its snippet from the build.
// The loaded metals, on the probe plane under the engine checks' lights, equal the CPU runtime's
// prediction for the material files `matc import` writes from the same asset (the textured ones
// at their F0 per pixel), to 1e-4.
//   node check-three-gltf.mjs MATC NPM_DIR
import { modulePage } from "./browser-page.mjs";
import { kThreeJsProbeTerms } from "./engine-probes.mjs";
import { kThreeGltfPageHead, kThreeGltfPageSetup, runLoaderCheck } from "./gltf-loader-checks.mjs";

const page = (config) => modulePage(config, {
  head: kThreeGltfPageHead,
  body: `${kThreeGltfPageSetup}
  const loads = await loadCarThreeWays(out, { matcGltfPlugin, matc, build, directoryBuild: await loadMatcBuild("/build/") });
  out.renders = {};
  for (const [load, probed] of Object.entries(config.probed)) {
    for (const [name, key] of Object.entries(probed)) {
      for (const light of config.lights) {
        out.renders[load + " " + key + " " + light + " r=0.3"] = renderProbePixels(renderer,
            probeScene(THREE, loads[load].byName[name], light, config, environment), camera, target, config.pixels);
      }
    }
  }
`,
});

await runLoaderCheck({
  engine: "three.js", page, terms: kThreeJsProbeTerms,
  summary: (worst) => `three.js GLTFLoader with matc's plugin: a glTF-Transform car asset's paint (coated), chrome ` +
              `and trims (textured, per pixel) became matc metals compiled in the page, the iridescent foil a filmed matc metal (its own table), the lacquered foil a coated one (its table the base lobe), the tyre kept three.js's material, largest difference from the CPU runtime ${worst.compiled.toExponential(2)}; ` +
              `from matc gltf's asset without the compiler, every metal took MATC_materials_fresnel's coefficients (the foils their films' tables), ` +
              `the coated paint its snippet from matc's template (${worst.extension.toExponential(2)}); ` +
              `with a build directory of the asset, the paint took its snippet from it ` +
              `(${worst.directory.toExponential(2)})`,
}, process.argv.slice(2));
