// glTF's metal-rough model per pixel in three.js (WebGLRenderer, or WebGPURenderer on Dawn with
// `webgpu`, headless Chromium): an asset
// whose metals take their metalness from a metallicRoughnessTexture (texels of metalness 0,
// 128/255 and 1) or a metallicFactor of 0.3 (gltf-assets.mjs, metalRoughAsset), loaded by
// three.js's own GLTFLoader and by the same loader with matc's plugin (compiled in the page). On
// the probe plane under the engine checks' three lights:
//   - a texel of metalness 0 renders as three.js's own material (matc replaces the metal only);
//   - one of metalness 1 as matc's metal: the CPU runtime's prediction for the material file
//     `matc import` writes (and the plain full metal of the same asset);
//   - half metal and the factor 0.3 as the mix: (1 - m) times the first plus m times the second;
//   - and three.js's own half metal differs from matc's there (the check is not vacuous).
//   node check-three-metal-rough.mjs MATC NPM_DIR [webgpu]
import { mkdirSync, mkdtempSync, rmSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { kWebRoots, modulePage, runPage } from "./browser-page.mjs";
import { compareProbes, expectedProbes, kPointLight, kProbePixels, kProbeRectLight, kProbeSize,
         kThreeJsProbeTerms } from "./engine-probes.mjs";
import { kThreeGltfPageHead, kThreeGltfPageSetup } from "./gltf-loader-checks.mjs";
import { kMetalRough, metalRoughAsset } from "./gltf-assets.mjs";
import { check, finish } from "./report.mjs";
import { kPreintegratedTolerance, run } from "./shader-cases.mjs";

const [matc, npmDir, renderer] = process.argv.slice(2);
const webGpu = renderer === "webgpu";
const kLights = ["environment", "point", "rect"];
const kNames = [...Object.keys(kMetalRough.textured), ...Object.keys(kMetalRough.factor), kMetalRough.plain];

// WebGPURenderer's page: the same loads through matc's WebGPU plugin (a WGSL build); WebGPURenderer
// draws three.js's own MeshStandardMaterial as its node material.
const kWebGpuHead = `import * as THREE from "three/webgpu";
import { GLTFLoader } from "three/addons/loaders/GLTFLoader.js";
import { RectAreaLightTexturesLib } from "three/addons/lights/RectAreaLightTexturesLib.js";
import { createMatc } from "/web/index.mjs";
import { compiledMatcBuildFiles } from "/web/matc-build.mjs";
import { loadMatcBuild } from "/web/three/matc-three-webgpu.mjs";
import { matcGltfPlugin } from "/web/three/matc-gltf-webgpu.mjs";
import { recordConsole } from "/checks/three-gltf-loads-page.mjs";
import { probeScene, webGpuProbeSetup, webGpuRenderer } from "/checks/three-scene-page.mjs";
`;
const kWebGpuSetup = `
  recordConsole(out);
  const renderer = await webGpuRenderer(THREE, RectAreaLightTexturesLib);
  const matc = await createMatc();
  const build = await loadMatcBuild(await compiledMatcBuildFiles(matc, { language: "wgsl" }));
  const { environment, renderPixels } = webGpuProbeSetup(THREE, renderer, ${kProbeSize});
`;
// Renders a probe scene's pixels (await works in both: WebGL's are ready at once).
const kWebGlRender = "renderProbePixels(renderer, scene, camera, target, config.pixels)";
const kWebGpuRender = "await renderPixels(scene, config.pixels)";

const page = (config) => modulePage(config, {
  head: webGpu ? kWebGpuHead : kThreeGltfPageHead,
  body: `${webGpu ? kWebGpuSetup : kThreeGltfPageSetup}
  out.renders = {};
  out.made = {};
  for (const [load, loader] of [["engine", new GLTFLoader()], ["matc", new GLTFLoader().register(matcGltfPlugin({ matc, build }))]]) {
    const gltf = await loader.loadAsync("/assets/metal_rough.glb");
    out.made[load] = (gltf.userData.matcMaterials ?? []).length;
    const byName = {};
    gltf.scene.traverse((object) => { if (object.isMesh) byName[object.material.name] = object.material; });
    for (const name of config.names) {
      for (const light of config.lights) {
        const scene = probeScene(THREE, byName[name], light, config, environment);
        out.renders[load + " " + name + " " + light] = ${webGpu ? kWebGpuRender : kWebGlRender};
      }
    }
  }
`,
});

const mixOf = (a, b, m) => a.map((rgb, i) => rgb.map((value, c) => (1 - m) * value + m * b[i][c]));
// The largest difference, relative to the value where it is above 1, as compareProbes counts it.
const difference = (a, b) => Math.max(...a.flatMap((rgb, i) => rgb.map((value, c) =>
  Math.abs(value - b[i][c]) / Math.max(1, Math.abs(b[i][c])))));

const dir = mkdtempSync(join(tmpdir(), "matc-metal-rough-"));
try {
  const assets = join(dir, "assets");
  mkdirSync(assets);
  const asset = join(assets, "metal_rough.glb");
  await metalRoughAsset(asset);
  const result = await runPage({
    html: page({ names: kNames, lights: kLights, pixels: kProbePixels, point: kPointLight, rect: kProbeRectLight }),
    roots: { ...kWebRoots, web: npmDir, assets }, dir, realTime: true, budgetMs: 120000,
    browserArgs: webGpu ? ["--enable-unsafe-webgpu", "--use-webgpu-adapter=swiftshader"] : [] });
  check(result.errors.length === 0, `page: ${result.errors.join("\n")}`);
  check(result.made?.engine === 0 && result.made?.matc === kNames.length,
        `matc metals made: ${JSON.stringify(result.made)}`);
  const warnings = (result.console ?? []).filter((line) => line.startsWith("warn:"));
  check(warnings.length === 0, `warnings: ${warnings.join("\n")}`);
  const render = (load, name, light) => result.renders?.[`${load} ${name} ${light}`] ?? [];
  let worst = 0, apart = 0;
  for (const light of kLights) {
    const dielectric = render("engine", "Metal 0", light);
    const metal = render("matc", kMetalRough.plain, light);
    const mixes = [["Metal 0", 0], ["Metal Half", kMetalRough.textured["Metal Half"] / 255], ["Metal Full", 1],
                   ["Metal Factor", kMetalRough.factor["Metal Factor"]]];
    for (const [name, metalness] of mixes) {
      const d = difference(render("matc", name, light), mixOf(dielectric, metal, metalness));
      worst = Math.max(worst, d);
      check(d <= kPreintegratedTolerance, `${name}, ${light}: ${d} from (1 - ${metalness}) three.js's own + ` +
                                          `${metalness} matc's metal`);
    }
    apart = Math.max(apart, difference(render("engine", "Metal Half", light), render("matc", "Metal Half", light)));
  }
  check(apart > 1e-3, `three.js's own half metal is within ${apart} of matc's: the check shows nothing`);
  // The full metal against the CPU runtime, for the material file matc import writes.
  const materials = join(dir, "materials");
  run(matc, ["import", "-q", "-o", materials, asset]);
  const out = join(dir, "out");
  run(matc, ["-q", "-o", out, "--emit", "json", join(materials, "Metal_Full.json")]);
  const expected = expectedProbes({ matc, materialsDir: materials, out, ...kThreeJsProbeTerms, bare: ["Metal_Full"],
                                    coated: [], renders: kLights.map((light) => ({ key: `Metal_Full ${light} r=0.3`, light })) });
  const cpu = compareProbes(Object.fromEntries(kLights.map((light) => [`Metal_Full ${light} r=0.3`, render("matc", "Metal Full", light)])),
                            expected);
  console.log(`three.js ${webGpu ? "WebGPURenderer" : "WebGLRenderer"}: GLTFLoader with matc's plugin, glTF's metal-rough model per pixel: metalness 0, 128/255, 1 ` +
              `(texture) and 0.3 (factor) within ${worst.toExponential(2)} of (1 - m) three.js's own material + m matc's ` +
              `metal under point, rect and image light; the full metal within ${cpu.toExponential(2)} of the CPU ` +
              `runtime; three.js's own half metal ${apart.toExponential(2)} away from matc's`);
} finally {
  rmSync(dir, { recursive: true, force: true });
}
finish();
