// matc's Fresnel inside three.js's own MeshPhysicalMaterial (js/package/three/matc-three.mjs),
// rendered by WebGLRenderer in headless Chromium into a float target and compared, at probe
// pixels, with what the CPU runtime (`matc eval`) predicts for the same normal, view, roughness
// and light, to 1e-4 (relative above 1):
//   - image lighting under a white environment (PMREM of a constant): compensated Fbar;
//   - a point light: irradiance x GGX (D, height-correlated Smith, as three.js writes them) x
//     matc's F(v.h) x matc's energy compensation;
//   - a rect area light: the light's radiance x `L_ltc` of `matc eval --quad-light`, and at the
//     quality level (areaLights "quality") x `L_ltc_following`;
// for the Figure 2 material and beryllium (compiled coefficients), a textured metal through the
// coefficient table, a `matc bake` result and a Schlick metal of the material's colour. Then the
// inputs that must fail: a build without
// the files the integration needs, a table of another basis than the build or the coefficients,
// and a three.js whose patched chunk changed; each must throw and write to the console.
//   node check-three-engine.mjs MATC MATERIALS_DIR EXAMPLES_WEB_DIR [--compile-in-page | --one-basis]
import { modulePage, threeVersion } from "./browser-page.mjs";
import { kProbeSize, kThreeJsProbeTerms, runProbeCheck } from "./engine-probes.mjs";


const kPage = (config) => modulePage(config, {
  head: `import * as THREE from "three";
import { KTX2Loader } from "three/addons/loaders/KTX2Loader.js";
import { RectAreaLightUniformsLib } from "three/addons/lights/RectAreaLightUniformsLib.js";
import { loadMatcBuild, useMatcFresnel } from "/web/three/matc-three.mjs";
import { checkBadInputs, recordConsoleErrors } from "/checks/page-bad-inputs.mjs";
import { probeScene, probeSetup, renderProbePixels } from "/checks/three-scene-page.mjs";
import { coatedF0TableSource, probeBuild } from "/checks/page-probe-build.mjs";
`,
  body: `
  out.renders = {};
  recordConsoleErrors(out);
  const renderer = new THREE.WebGLRenderer({ canvas: document.createElement("canvas") });
  renderer.debug.onShaderError = (gl, program, vertex, fragment) =>
    out.errors.push(gl.getShaderInfoLog(fragment) || gl.getShaderInfoLog(vertex) || gl.getProgramInfoLog(program));
  RectAreaLightUniformsLib.init();
  const { build, directoryBuild, loadProbeMaterial } = await probeBuild(out, config, loadMatcBuild);
  const { target, camera, environment } = probeSetup(THREE, renderer, ${kProbeSize});
  const constant = (rgb) => {
    const texture = new THREE.DataTexture(new Float32Array([...rgb, 1]), 1, 1, THREE.RGBAFormat, THREE.FloatType);
    texture.needsUpdate = true;
    return texture;
  };
  const ktx2 = new KTX2Loader().detectSupport(renderer);
  const baked = async (name) => ktx2.loadAsync("/baked/" + name);
  const sources = {};
  for (const name of config.materials) sources[name] = { material: await loadProbeMaterial(name) };
  sources.textured = { reflectivityMap: constant(config.textured.reflectivity),
                       edgeTintMap: constant(config.textured.edgeTint) };
  sources.baked = { baked: { c2Map: await baked("probe_c2.ktx2"), c3Map: await baked("probe_c3.ktx2"),
                             f0Map: await baked("probe_f0.ktx2") } };
  sources.schlick = { schlick: { basis: config.schlick.basis, zeroF0Coefficients: config.schlick.zeroF0Coefficients } };
  sources.f0table = { material: { name: "f0_table_probe", basis: config.f0Table.basis, coefficients: config.f0Table.coefficients[0], coat: null },
                      f0Table: { coefficients: config.f0Table.coefficients } };
  // The coated F0-table metal, at the material's colour too.
  sources[config.f0TableCoated.name] = await coatedF0TableSource(build, config);
  const tableColour = (source) => source === "f0table" || source === config.f0TableCoated.name;
  for (const render of config.renders) {
    // The Schlick and F0-table metals' F0 is the material's colour (linear).
    const colour = render.source === "schlick" ? { color: new THREE.Color(...config.schlick.color) }
                 : tableColour(render.source) ? { color: new THREE.Color(...config.f0Table.color) } : {};
    const material = useMatcFresnel(new THREE.MeshPhysicalMaterial({ roughness: render.roughness, ...colour }),
                                    build, sources[render.source], { areaLights: render.areaLights });
    out.renders[render.key] = renderProbePixels(renderer, probeScene(THREE, material, render.light, config, environment),
                                                camera, target, config.pixels);
  }
  const original = THREE.ShaderChunk.lights_physical_pars_fragment;
  await checkBadInputs(out, {
    loadMatcBuild, build: directoryBuild, material: sources.beryllium.material, coated: sources[config.coated].material, filmed: sources[config.filmed].material,
    texture: constant([1, 1, 1]),
    useMatc: (source, options) => useMatcFresnel(new THREE.MeshPhysicalMaterial(), build, source, options),
    changeEngine: () => {
      THREE.ShaderChunk.lights_physical_pars_fragment =
          original.replaceAll("F_Schlick( f0, f90, dotVH )", "F_Schlick( f0, f90, saturate( dotVH ) )");
      return () => { THREE.ShaderChunk.lights_physical_pars_fragment = original; };
    } });
`,
});

await runProbeCheck({
  name: "three.js", label: `three.js ${threeVersion()} MeshPhysicalMaterial`, page: kPage,
  ...kThreeJsProbeTerms,
}, process.argv.slice(2));
