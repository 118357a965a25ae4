// glTF's metal-rough model per pixel in the web engines (three.js's WebGLRenderer, its
// WebGPURenderer on Dawn with `three-webgpu`, Babylon.js with `babylon`; headless Chromium): an
// asset whose metals take their metalness from a metallicRoughnessTexture (texels of metalness 0,
// 128/255 and 1) or a metallicFactor of 0.3 (gltf-assets.mjs, metalRoughAsset), loaded by the
// engine's own glTF loader and by the same loader with matc's (compiled in the page). On the
// probe plane under the engine checks' three lights:
//   - a texel of metalness 0 renders as the engine's own material (matc replaces the metal only);
//   - one of metalness 1 as matc's metal: the CPU runtime's prediction for the material file
//     `matc import` writes (and the plain full metal of the same asset);
//   - half metal and the factor 0.3 as the mix: (1 - m) times the first plus m times the second
//     (Babylon.js scales its diffuse by a Fresnel of its blended F0, not linear in m: there the
//     mix is checked on the same asset with a black base colour, which has no diffuse);
//   - and the engine's own half metal differs from matc's there (the check is not vacuous).
// The same asset under a KHR_materials_clearcoat (metal_rough_coated.glb): matc's coat lobe over
// the mix of matc's ends; the full metal as the CPU runtime's coated metal (both lobes); a texel of
// metalness 0 as the engine's own uncoated dielectric times the coat's transmission at the pixel's
// NdotV (1 - the coat lobe's F, matc eval) under the CPU runtime's coat lobe. And under an edge
// colour (metal_rough_edge.glb, EXT_materials_specular_edge_color; Babylon.js's OpenPBR conductor
// model): the mix, and the full metal as the CPU runtime's edge-coloured metal.
//   node check-gltf-metal-rough.mjs MATC NPM_DIR [three|three-webgpu|babylon]
import { mkdirSync, mkdtempSync, rmSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { kWebRoots, modulePage, runPage } from "./browser-page.mjs";
import { compareProbes, expectedProbes, kBabylonProbeTerms, kPointLight, kProbePixels, kProbeRectLight, kProbeSize,
         kThreeJsProbeTerms, probeNdotV } from "./engine-probes.mjs";
import { kThreeGltfPageHead, kThreeGltfPageSetup } from "./gltf-loader-checks.mjs";
import { kMetalRough, metalRoughAsset } from "./gltf-assets.mjs";
import { check, finish } from "./report.mjs";
import { run } from "./shader-cases.mjs";

const [matc, npmDir, engine = "three"] = process.argv.slice(2);
const webGpu = engine === "three-webgpu";
const babylon = engine === "babylon";
const engineName = { three: "three.js (WebGLRenderer)", "three-webgpu": "three.js (WebGPURenderer)", babylon: "Babylon.js" }[engine];
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

// Babylon.js's page: its glTF loader with and without matc's extension registered.
const babylonPage = (config) => modulePage(config, {
  head: `import "@babylonjs/loaders/glTF/2.0/index.js";
import { LoadAssetContainerAsync } from "@babylonjs/core/Loading/sceneLoader.js";
import { createMatc } from "/web/index.mjs";
import { compiledMatcBuildFiles } from "/web/matc-build.mjs";
import { loadMatcBuild } from "/web/babylon/matc-babylon.mjs";
import { registerMatcGltfExtension } from "/web/babylon/matc-gltf.mjs";
import { recordConsole } from "/checks/three-gltf-loads-page.mjs";
import { babylonProbeScene, renderBabylonProbe } from "/checks/babylon-scene-page.mjs";
`,
  body: `
  recordConsole(out);
  const { scene, camera } = babylonProbeScene(${kProbeSize});
  const matc = await createMatc();
  const build = await loadMatcBuild(await compiledMatcBuildFiles(matc), scene);
  out.renders = {};
  out.made = {};
  for (const asset of config.assets) {
    for (const load of ["engine", "matc"]) {
      const registration = load === "matc" ? registerMatcGltfExtension({ matc, build }) : null;
      let container;
      try {
        container = await LoadAssetContainerAsync("/assets/" + asset + ".glb", scene);
      } finally {
        registration?.unregister();
      }
      out.made[asset + " " + load] = registration ? registration.materials.length : 0;
      const byName = Object.fromEntries(container.materials.map((material) => [material.name, material]));
      for (const name of config.names) {
        for (const light of config.lights) {
          const key = asset + " " + load + " " + name + " " + light;
          out.renders[key] = await renderBabylonProbe({ scene, camera, material: byName[name], light, config,
                                                        size: ${kProbeSize}, out, key });
        }
      }
    }
  }
`,
});

const threePage = (config) => modulePage(config, {
  head: webGpu ? kWebGpuHead : kThreeGltfPageHead,
  body: `${webGpu ? kWebGpuSetup : kThreeGltfPageSetup}
  out.renders = {};
  out.made = {};
  for (const asset of config.assets) {
    for (const [load, loader] of [["engine", new GLTFLoader()], ["matc", new GLTFLoader().register(matcGltfPlugin({ matc, build }))]]) {
      const gltf = await loader.loadAsync("/assets/" + asset + ".glb");
      out.made[asset + " " + load] = (gltf.userData.matcMaterials ?? []).length;
      const byName = {};
      gltf.scene.traverse((object) => { if (object.isMesh) byName[object.material.name] = object.material; });
      for (const name of config.names) {
        for (const light of config.lights) {
          const scene = probeScene(THREE, byName[name], light, config, environment);
          out.renders[asset + " " + load + " " + name + " " + light] = ${webGpu ? kWebGpuRender : kWebGlRender};
        }
      }
    }
  }
`,
});

// Renders against renders of the same engine and pass: float32 rounding apart (1e-7 measured),
// tighter than the CPU comparison's 1e-4 so that a lobe's missing energy factor (4e-5) shows.
const kMixTolerance = 1e-5;
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
  // Under a clear coat too; Babylon.js: the mix on a black base colour as well (no diffuse; see above).
  await metalRoughAsset(join(assets, "metal_rough_coated.glb"), { coat: kMetalRough.coat });
  await metalRoughAsset(join(assets, "metal_rough_edge.glb"), { edge: kMetalRough.edge });
  const names = ["metal_rough", "metal_rough_coated", "metal_rough_edge"];
  if (babylon) {
    await metalRoughAsset(join(assets, "metal_rough_black.glb"), { baseColor: [0, 0, 0] });
    await metalRoughAsset(join(assets, "metal_rough_coated_black.glb"), { baseColor: [0, 0, 0], coat: kMetalRough.coat });
    names.push("metal_rough_black", "metal_rough_coated_black");
  }
  const config = { names: kNames, assets: names, lights: kLights, pixels: kProbePixels, point: kPointLight, rect: kProbeRectLight };
  const result = await runPage({
    html: (babylon ? babylonPage : threePage)(config),
    roots: { ...kWebRoots, web: npmDir, assets }, dir, realTime: true, budgetMs: 120000,
    browserArgs: webGpu ? ["--enable-unsafe-webgpu", "--use-webgpu-adapter=swiftshader"] : [] });
  check(result.errors.length === 0, `page: ${result.errors.join("\n")}`);
  for (const name of names) {
    check(result.made?.[`${name} engine`] === 0 && result.made?.[`${name} matc`] === kNames.length,
          `${name}: matc metals made: ${JSON.stringify(result.made)}`);
  }
  const warnings = (result.console ?? []).filter((line) => line.startsWith("warn:"));
  check(warnings.length === 0, `warnings: ${warnings.join("\n")}`);
  const render = (assetName, load, name, light) => result.renders?.[`${assetName} ${load} ${name} ${light}`] ?? [];
  const mixes = [["Metal 0", 0], ["Metal Half", kMetalRough.textured["Metal Half"] / 255], ["Metal Full", 1],
                 ["Metal Factor", kMetalRough.factor["Metal Factor"]]];
  let worst = 0, apart = 0;
  for (const assetName of names) {
    const coated = assetName.includes("coated");
    // Babylon.js's coloured assets: the ends (the engine's own at 0, matc's metal at 1).
    const checked = babylon && !assetName.includes("black") ? mixes.filter(([, m]) => m === 0 || m === 1) : mixes;
    for (const light of kLights) {
      // Under a coat, matc's coat lobe (the coat's exact Fresnel, where the engine has Schlick's)
      // lies over the dielectric too: the ends are matc's renders (the non-metal one checked below).
      const dielectric = render(assetName, coated ? "matc" : "engine", "Metal 0", light);
      const metal = render(assetName, "matc", kMetalRough.plain, light);

      for (const [name, metalness] of checked) {
        const d = difference(render(assetName, "matc", name, light), mixOf(dielectric, metal, metalness));
        worst = Math.max(worst, d);
        check(d <= kMixTolerance, `${assetName}: ${name}, ${light}: ${d} from (1 - ${metalness}) the engine's ` +
                                            `own + ${metalness} matc's metal`);
      }
      apart = Math.max(apart, difference(render(assetName, "engine", "Metal Half", light),
                                         render(assetName, "matc", "Metal Half", light)));
    }
  }
  check(apart > 1e-3, `the engine's own half metal is within ${apart} of matc's: the check shows nothing`);
  // The full metal against the CPU runtime, for the material file matc import writes.
  const materials = join(dir, "materials");
  run(matc, ["import", "-q", "-o", materials, asset]);
  const out = join(dir, "out");
  run(matc, ["-q", "-o", out, "--emit", "json", join(materials, "Metal_Full.json")]);
  const terms = babylon ? kBabylonProbeTerms : kThreeJsProbeTerms;
  const expected = expectedProbes({ matc, materialsDir: materials, out, ...terms, bare: ["Metal_Full"],
                                    coated: [], renders: kLights.map((light) => ({ key: `Metal_Full ${light} r=0.3`, light })) });
  const cpu = compareProbes(Object.fromEntries(kLights.map((light) =>
    [`Metal_Full ${light} r=0.3`, render("metal_rough", "matc", "Metal Full", light)])), expected);
  // The same under the coat: both lobes as the CPU runtime evaluates them.
  const coatedMaterials = join(dir, "materials_coated");
  run(matc, ["import", "-q", "-o", coatedMaterials, join(assets, "metal_rough_coated.glb")]);
  const coatedOut = join(dir, "out_coated");
  run(matc, ["-q", "-o", coatedOut, "--emit", "json", join(coatedMaterials, "Metal_Full.json")]);
  const expectedCoated = expectedProbes({
    matc, materialsDir: coatedMaterials, out: coatedOut, ...terms, bare: [], coated: ["Metal_Full"],
    renders: kLights.map((light) => ({ key: `Metal_Full ${light} r=0.3`, light })) });
  const cpuCoated = compareProbes(Object.fromEntries(kLights.map((light) =>
    [`Metal_Full ${light} r=0.3`, render("metal_rough_coated", "matc", "Metal Full", light)])), expectedCoated);
  // A non-metal texel under the coat: the engine's own uncoated dielectric times the coat's
  // transmission at the pixel's NdotV (glTF's layering: 1 - the coat lobe's F there, from matc eval),
  // under matc's coat lobe (the CPU runtime's).
  const coatLobe = expectedProbes({
    matc, materialsDir: coatedMaterials, out: coatedOut, ...terms, bare: [], coated: ["Metal_Full"], coatLobeOnly: true,
    renders: kLights.map((light) => ({ key: `Metal_Full ${light} r=0.3`, light })) });
  const ndotv = kProbePixels.map((pixel) => Math.fround(probeNdotV(pixel)));
  const coatF = JSON.parse(run(matc, ["eval", join(coatedMaterials, "Metal_Full.json"), "--no-reference",
                                      "--mu", ndotv.join(",")])).F_coat;
  const dielectricExpected = {}, dielectricRendered = {};
  for (const light of kLights) {
    const key = `Metal_0 ${light}`;
    dielectricExpected[key] = render("metal_rough", "engine", "Metal 0", light).map((rgb, i) =>
      rgb.map((value, c) => (1 - coatF[i]) * value + coatLobe[`Metal_Full ${light} r=0.3`][i][c]));
    dielectricRendered[key] = render("metal_rough_coated", "matc", "Metal 0", light);
  }
  const coatedDielectric = compareProbes(dielectricRendered, dielectricExpected);
  const ownCoat = Math.max(...kLights.map((light) => difference(render("metal_rough_coated", "matc", "Metal 0", light),
                                                                 render("metal_rough_coated", "engine", "Metal 0", light))));
  // The edge-coloured full metal (F82 tint; Babylon.js's OpenPBR conductor model) against the CPU runtime.
  const edgeMaterials = join(dir, "materials_edge");
  run(matc, ["import", "-q", "-o", edgeMaterials, join(assets, "metal_rough_edge.glb")]);
  const edgeOut = join(dir, "out_edge");
  run(matc, ["-q", "-o", edgeOut, "--emit", "json", join(edgeMaterials, "Metal_Full.json")]);
  const expectedEdge = expectedProbes({ matc, materialsDir: edgeMaterials, out: edgeOut, ...terms, bare: ["Metal_Full"],
                                        coated: [], renders: kLights.map((light) => ({ key: `Metal_Full ${light} r=0.3`, light })) });
  const cpuEdge = compareProbes(Object.fromEntries(kLights.map((light) =>
    [`Metal_Full ${light} r=0.3`, render("metal_rough_edge", "matc", "Metal Full", light)])), expectedEdge);
  console.log(`${engineName}: its glTF loader with matc's, glTF's metal-rough model per pixel: metalness 0, 128/255, 1 ` +
              `(texture) and 0.3 (factor) within ${worst.toExponential(2)} of (1 - m) the engine's own material + m matc's ` +
              `metal under point, rect and image light${babylon ? " (the mix on a black base colour)" : ""}; the full ` +
              `metal within ${cpu.toExponential(2)} of the CPU runtime; the engine's own half metal ` +
              `${apart.toExponential(2)} away from matc's. Under a clear coat (factor ${kMetalRough.coat.factor}): ` +
              `the same mix of matc's ends, the full metal within ${cpuCoated.toExponential(2)} of the CPU runtime, ` +
              `a non-metal texel within ${coatedDielectric.toExponential(2)} of the engine's own dielectric through ` +
              `matc's coat (the engine's own clear coat ${ownCoat.toExponential(2)} away). Under an edge colour ` +
              `(EXT_materials_specular_edge_color${babylon ? ", Babylon.js's OpenPBR conductor model" : ""}): the mix as above, ` +
              `the full metal within ${cpuEdge.toExponential(2)} of the CPU runtime`);
} finally {
  rmSync(dir, { recursive: true, force: true });
}
finish();
