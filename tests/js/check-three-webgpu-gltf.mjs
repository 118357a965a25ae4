// The three.js GLTFLoader plugin for WebGPURenderer (js/package/three/matc-gltf-webgpu.mjs), on
// WebGPU in headless Chromium (Dawn on SwiftShader): the car asset of check-three-gltf.mjs loaded
// by three.js's own GLTFLoader the same three ways (compiled in the page by a WGSL build; as `matc
// gltf` wrote it, with no compiler, the coated paint's WGSL snippet from matc's template filled
// with the extension's values; with a build directory that compiled the asset). Each metal
// becomes a node material drawn by matc's lighting model; the loaded metals, on the probe plane
// under the engine checks' lights, equal the CPU runtime's prediction to 1e-4.
//   node check-three-webgpu-gltf.mjs MATC NPM_DIR
import { modulePage } from "./browser-page.mjs";
import { kProbeSize, kThreeJsProbeTerms } from "./engine-probes.mjs";
import { runLoaderCheck } from "./gltf-loader-checks.mjs";
import { check } from "./report.mjs";

const page = (config) => modulePage(config, {
  head: `import * as THREE from "three/webgpu";
import { RectAreaLightTexturesLib } from "three/addons/lights/RectAreaLightTexturesLib.js";
import { createMatc } from "/web/index.mjs";
import { compiledMatcBuildFiles } from "/web/matc-build.mjs";
import { loadMatcBuild } from "/web/three/matc-three-webgpu.mjs";
import { matcGltfPlugin } from "/web/three/matc-gltf-webgpu.mjs";
import { loadCarThreeWays, recordConsole } from "/checks/three-gltf-loads-page.mjs";
import { probeScene, webGpuProbeSetup, webGpuRenderer } from "/checks/three-scene-page.mjs";
`,
  body: `
  recordConsole(out);
  const renderer = await webGpuRenderer(THREE, RectAreaLightTexturesLib);
  const matc = await createMatc();
  const build = await loadMatcBuild(await compiledMatcBuildFiles(matc, { language: "wgsl" }));
  // Options it cannot use, refused by name when the plugin is made.
  out.refusals = [{ build: null }, { build: { loadMaterial() {} } }].map((options) => {
    try {
      matcGltfPlugin(options);
      return "no error";
    } catch (error) {
      return error.message;
    }
  });
  const loads = await loadCarThreeWays(out, { matcGltfPlugin, matc, build, directoryBuild: await loadMatcBuild("/build/") });
  // A matc metal is a node material, on the meshes that used three.js's (byName reads the meshes).
  for (const [name, load] of Object.entries(loads)) {
    if (load.made.some((material) => !material.isMeshStandardNodeMaterial)) throw new Error(name + ": a matc metal that is not a node material");
  }
  const { environment, renderPixels } = webGpuProbeSetup(THREE, renderer, ${kProbeSize});
  out.renders = {};
  for (const [load, probed] of Object.entries(config.probed)) {
    for (const [name, key] of Object.entries(probed)) {
      for (const light of config.lights) {
        out.renders[load + " " + key + " " + light + " r=0.3"] =
            await renderPixels(probeScene(THREE, loads[load].byName[name], light, config, environment), config.pixels);
      }
    }
  }
`,
});

await runLoaderCheck({
  engine: "three.js", page, terms: kThreeJsProbeTerms,
  browserArgs: ["--enable-unsafe-webgpu", "--use-webgpu-adapter=swiftshader"],
  checkResult: (result) => {
    const [none, webgl] = result.refusals ?? [];
    check(/matcGltfPlugin \(WebGPU\) takes \{ build: await loadMatcBuild/.test(none), `no build: ${none}`);
    check(/matcGltfPlugin \(WebGPU\) takes matc\/three\/webgpu's loadMatcBuild\(\.\.\.\), a WGSL build/.test(webgl),
          `a build of another module: ${webgl}`);
  },
  summary: (worst) => `three.js GLTFLoader with matc's WebGPU plugin, on WebGPURenderer: the car asset's paint (coated), ` +
              `chrome and trims (textured, per pixel) became matc node materials compiled in the page (WGSL), the iridescent foil a filmed matc metal (its own table), the lacquered foil a coated one (its table the base lobe), the tyre kept three.js's material, largest difference from the CPU ` +
              `runtime ${worst.compiled.toExponential(2)}; from matc gltf's asset without the compiler, every metal took ` +
              `MATC_materials_fresnel's coefficients (the foils their films' tables), the coated paint its snippet from matc's WGSL template ` +
              `(${worst.extension.toExponential(2)}); with a build directory of the asset, the paint took its snippet ` +
              `from it (${worst.directory.toExponential(2)})`,
}, process.argv.slice(2));
