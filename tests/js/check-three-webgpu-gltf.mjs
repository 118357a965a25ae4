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
import { GLTFLoader } from "three/addons/loaders/GLTFLoader.js";
import { RectAreaLightTexturesLib } from "three/addons/lights/RectAreaLightTexturesLib.js";
import { createMatc } from "/web/index.mjs";
import { compiledMatcBuildFiles } from "/web/matc-build.mjs";
import { loadMatcBuild } from "/web/three/matc-three-webgpu.mjs";
import { matcGltfPlugin } from "/web/three/matc-gltf-webgpu.mjs";
import { probeScene, webGpuRenderer } from "/checks/three-scene-page.mjs";
`,
  body: `
  out.console = [];
  for (const level of ["error", "warn"]) {
    const original = console[level].bind(console);
    console[level] = (...args) => { out.console.push(level + ": " + args.join(" ")); original(...args); };
  }
  const renderer = await webGpuRenderer(THREE, RectAreaLightTexturesLib);
  const matc = await createMatc();
  const build = await loadMatcBuild(await compiledMatcBuildFiles(matc, { language: "wgsl" }));
  const load = async (url, plugin) => {
    const gltf = await new GLTFLoader().register(plugin).loadAsync(url);
    const byName = {};
    gltf.scene.traverse((object) => { if (object.isMesh) byName[object.material.name] = object.material; });
    const kinds = Object.fromEntries(Object.entries(byName).map(([name, material]) =>
      [name, material.userData.matc ? (material.userData.matc.source.schlick ? "per-pixel" :
                                       (material.userData.matc.source.f0Table ? "f0-table " : "") +
                                       (material.userData.matc.source.material.coat ? "coated" : "bare")) +
                                      " " + material.userData.matc.from +
                                      (/from MATC_materials_fresnel/.test(material.userData.matc.source.material?.coat?.snippet) ?
                                       " (template)" : "") : "engine"]));
    // A matc metal is a node material, on the meshes that used three.js's (byName reads the meshes).
    if (gltf.userData.matcMaterials.some((material) => !material.isMeshStandardNodeMaterial)) {
      throw new Error(url + ": a matc metal that is not a node material");
    }
    return { byName, kinds, made: gltf.userData.matcMaterials.length };
  };
  // Options it cannot use, refused by name when the plugin is made.
  out.refusals = [{ build: null }, { build: { loadMaterial() {} } }].map((options) => {
    try {
      matcGltfPlugin(options);
      return "no error";
    } catch (error) {
      return error.message;
    }
  });
  const loads = {};
  for (const [name, url, options] of [["compiled", "/assets/car.glb", { matc, build }],
                                      ["extension", "/assets/car_matc.glb", { build }],
                                      ["directory", "/assets/car_matc.glb", { build: await loadMatcBuild("/build/") }]]) {
    out.console.push("-- " + name);
    loads[name] = await load(url, matcGltfPlugin(options));
  }
  out.kinds = Object.fromEntries(Object.entries(loads).map(([name, load]) => [name, load.kinds]));
  out.made = Object.fromEntries(Object.entries(loads).map(([name, load]) => [name, load.made]));
  const target = new THREE.RenderTarget(${kProbeSize}, ${kProbeSize}, { type: THREE.FloatType });
  const camera = new THREE.PerspectiveCamera(90, 1, 0.1, 10);
  camera.position.set(0, 0, 1);
  const white = new THREE.DataTexture(new Float32Array(64 * 32 * 4).fill(1), 64, 32, THREE.RGBAFormat, THREE.FloatType);
  white.mapping = THREE.EquirectangularReflectionMapping;
  white.needsUpdate = true;
  out.renders = {};
  for (const [load, probed] of Object.entries(config.probed)) {
    for (const [name, key] of Object.entries(probed)) {
      for (const light of config.lights) {
        renderer.setRenderTarget(target);
        renderer.render(probeScene(THREE, loads[load].byName[name], light, config, white), camera);
        const pixels = [];
        for (const [x, y] of config.pixels) {
          const texel = await renderer.readRenderTargetPixelsAsync(target, x, ${kProbeSize} - 1 - y, 1, 1);
          pixels.push(Array.from(texel.subarray(0, 3)));
        }
        out.renders[load + " " + key + " " + light + " r=0.3"] = pixels;
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
              `chrome and trims (textured, per pixel) became matc node materials compiled in the page (WGSL), the tyre and ` +
              `the iridescent foil kept three.js's material (the foil with a warning), largest difference from the CPU ` +
              `runtime ${worst.compiled.toExponential(2)}; from matc gltf's asset without the compiler, every metal took ` +
              `MATC_materials_fresnel's coefficients, the coated paint its snippet from matc's WGSL template ` +
              `(${worst.extension.toExponential(2)}); with a build directory of the asset, the paint took its snippet ` +
              `from it (${worst.directory.toExponential(2)})`,
}, process.argv.slice(2));
