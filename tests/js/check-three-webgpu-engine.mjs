// matc's Fresnel in three.js's WebGPURenderer (js/package/three/matc-three-webgpu.mjs: three's
// PhysicalLightingModel with matc's WGSL library through wgslFn), on WebGPU in headless Chromium
// (Dawn on SwiftShader), at the probe pixels of tests/js/engine-probes.mjs under the white
// environment, the point light and the rect area light (matc's LTC, and at the quality level), for
// the Figure 2 material and beryllium at two roughnesses, a textured metal through the coefficient
// table, a `matc bake` result and a Schlick metal of the material's colour, against the CPU
// runtime to 1e-4. WebGPU's adapter and device do not settle under Chromium's virtual time: the
// page runs in real time and posts its result.
//   node check-three-webgpu-engine.mjs MATC MATERIALS_DIR EXAMPLES_WEB_DIR [--compile-in-page | --one-basis]
import { modulePage, threeVersion } from "./browser-page.mjs";
import { kProbeSize, kThreeJsProbeTerms, runProbeCheck } from "./engine-probes.mjs";

const kPage = (config) => modulePage(config, {
  head: `import * as THREE from "three/webgpu";
import { read as readKtx2 } from "ktx-parse";
import { RectAreaLightTexturesLib } from "three/addons/lights/RectAreaLightTexturesLib.js";
import { loadMatcBuild, useMatcFresnel } from "/web/three/matc-three-webgpu.mjs";
import { checkBadInputs, recordConsoleErrors } from "/checks/page-bad-inputs.mjs";
import { probeScene, webGpuProbeSetup, webGpuRenderer } from "/checks/three-scene-page.mjs";
import { coatedF0TableSource, probeBuild } from "/checks/page-probe-build.mjs";`,
  body: `
  out.renders = {};
  recordConsoleErrors(out);
  const renderer = await webGpuRenderer(THREE, RectAreaLightTexturesLib);
  const { build, directoryBuild, loadProbeMaterial } =
      await probeBuild(out, config, loadMatcBuild, { language: "wgsl" });
  const { environment: white, renderPixels } = webGpuProbeSetup(THREE, renderer, ${kProbeSize});
  const materials = {};
  for (const name of config.materials) materials[name] = await loadProbeMaterial(name);
  const constant = (rgb) => {
    const texture = new THREE.DataTexture(new Float32Array([...rgb, 1]), 1, 1, THREE.RGBAFormat, THREE.FloatType);
    texture.needsUpdate = true;
    return texture;
  };
  const baked = async (file) => {
    const container = readKtx2(new Uint8Array(await (await fetch("/baked/" + file)).arrayBuffer()));
    const level = container.levels[0].levelData;
    const texture = new THREE.DataTexture(new Float32Array(level.buffer.slice(level.byteOffset, level.byteOffset + level.byteLength)),
                                          container.pixelWidth, container.pixelHeight, THREE.RGBAFormat, THREE.FloatType);
    texture.needsUpdate = true;
    return texture;
  };
  const sources = {
    textured: { reflectivityMap: constant(config.textured.reflectivity), edgeTintMap: constant(config.textured.edgeTint) },
    baked: { baked: { c2Map: await baked("probe_c2.ktx2"), c3Map: await baked("probe_c3.ktx2"), f0Map: await baked("probe_f0.ktx2") } },
    schlick: { schlick: { basis: config.schlick.basis, zeroF0Coefficients: config.schlick.zeroF0Coefficients } },
    f0table: { material: { name: "f0_table_probe", basis: config.f0Table.basis, coefficients: config.f0Table.coefficients[0], coat: null },
                      f0Table: { coefficients: config.f0Table.coefficients } },
  };
  // The coated F0-table metal, at the material's colour too.
  sources[config.f0TableCoated.name] = await coatedF0TableSource(build, config);
  const tableColour = (source) => source === "f0table" || source === config.f0TableCoated.name;
  for (const render of config.renders) {
    // The Schlick and F0-table metals' F0 is the material's colour (linear).
    const colour = render.source === "schlick" ? { color: new THREE.Color(...config.schlick.color) }
                 : tableColour(render.source) ? { color: new THREE.Color(...config.f0Table.color) } : {};
    const material = useMatcFresnel(new THREE.MeshPhysicalNodeMaterial({ roughness: render.roughness, ...colour }), build,
                                    sources[render.source] ?? { material: materials[render.source] },
                                    { areaLights: render.areaLights });
    out.renders[render.key] = await renderPixels(probeScene(THREE, material, render.light, config, white), config.pixels);
  }
  const lightingModel = THREE.PhysicalLightingModel.prototype;
  const original = lightingModel.indirectSpecular;
  await checkBadInputs(out, {
    loadMatcBuild, build: directoryBuild, material: materials.beryllium, coated: materials[config.coated], filmed: materials[config.filmed], texture: white,
    useMatc: (source, options) => useMatcFresnel(new THREE.MeshPhysicalNodeMaterial(), build, source, options),
    changeEngine: () => {
      // A three.js whose metal image lighting no longer goes through computeMultiscattering.
      lightingModel.indirectSpecular = function (builder) { return original.call(this, builder); };
      return () => { lightingModel.indirectSpecular = original; };
    } });`,
});

await runProbeCheck({
  name: "three.js WebGPURenderer", label: `three.js ${threeVersion()} WebGPURenderer MeshPhysicalNodeMaterial`,
  page: kPage, ...kThreeJsProbeTerms,
  runPage: { realTime: true, budgetMs: 120000, browserArgs: ["--enable-unsafe-webgpu", "--use-webgpu-adapter=swiftshader"] },
}, process.argv.slice(2));
