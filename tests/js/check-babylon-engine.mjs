// matc's Fresnel inside Babylon.js's PBRMaterial (js/package/babylon/matc-babylon.mjs, a
// material plugin), rendered by Babylon's WebGL2 engine in headless Chromium into a float render
// target and compared, at probe pixels, with what the CPU runtime (`matc eval`) predicts, to 1e-4
// (relative above 1): under a white environment, a point light and a rect area light (also at the
// quality level, areaLights "quality"), for the Figure 2 material and beryllium, a textured metal
// through the coefficient table, a `matc bake` result, a Schlick metal of the albedo colour
// (tests/js/engine-probes.mjs has the scene
// and the CPU side). Then the inputs that must fail, as for three.js, with a Babylon whose patched
// shader changed.
//   node check-babylon-engine.mjs MATC MATERIALS_DIR EXAMPLES_WEB_DIR [--compile-in-page | --one-basis]
import { readFileSync } from "node:fs";
import { dirname, join } from "node:path";
import { fileURLToPath } from "node:url";
import { modulePage } from "./browser-page.mjs";
import { kBabylonProbeTerms, kProbeSize, runProbeCheck } from "./engine-probes.mjs";

const kPage = (config) => modulePage(config, {
  head: `import { Constants } from "@babylonjs/core/Engines/constants.js";
import { PBRMaterial } from "@babylonjs/core/Materials/PBR/pbrMaterial.js";
import { RawTexture } from "@babylonjs/core/Materials/Textures/rawTexture.js";
import { ShaderStore } from "@babylonjs/core/Engines/shaderStore.js";
import { read as readKtx2 } from "ktx-parse";
import { babylonProbeScene, renderBabylonProbe } from "/checks/babylon-scene-page.mjs";
import { coatedF0TableSource, probeBuild } from "/checks/page-probe-build.mjs";
import { loadMatcBuild, useMatcFresnel } from "/web/babylon/matc-babylon.mjs";
import { checkBadInputs, recordConsoleErrors } from "/checks/page-bad-inputs.mjs";
`,
  body: `
  out.renders = {};
  recordConsoleErrors(out);
  const { scene, camera } = babylonProbeScene(${kProbeSize});
  const { build, directoryBuild, loadProbeMaterial } =
      await probeBuild(out, config, (source) => loadMatcBuild(source, scene));
  const constant = (scene, rgb) => new RawTexture(new Float32Array([...rgb, 1]), 1, 1, Constants.TEXTUREFORMAT_RGBA,
                                                  scene, false, false, Constants.TEXTURE_NEAREST_SAMPLINGMODE,
                                                  Constants.TEXTURETYPE_FLOAT);
  const baked = async (scene, file) => {
    const container = readKtx2(new Uint8Array(await (await fetch("/baked/" + file)).arrayBuffer()));
    const level = container.levels[0].levelData;
    return new RawTexture(new Float32Array(level.buffer.slice(level.byteOffset, level.byteOffset + level.byteLength)),
                          container.pixelWidth, container.pixelHeight, Constants.TEXTUREFORMAT_RGBA, scene, false,
                          false, Constants.TEXTURE_BILINEAR_SAMPLINGMODE, Constants.TEXTURETYPE_FLOAT);
  };
  const materials = {};
  for (const name of config.materials) materials[name] = await loadProbeMaterial(name);
  // The coated F0-table metal, at the material's colour too.
  const coatedTable = await coatedF0TableSource(build, config);
  const tableColour = (source) => source === "f0table" || source === config.f0TableCoated.name;
  for (const render of config.renders) {
    const made = [];  // what this render adds to the scene, disposed after it
    const sources = {
      textured: () => ({ reflectivityMap: constant(scene, config.textured.reflectivity),
                         edgeTintMap: constant(scene, config.textured.edgeTint) }),
      baked: async () => ({ baked: { c2Map: await baked(scene, "probe_c2.ktx2"), c3Map: await baked(scene, "probe_c3.ktx2"),
                                     f0Map: await baked(scene, "probe_f0.ktx2") } }),
      schlick: () => ({ schlick: { basis: config.schlick.basis, zeroF0Coefficients: config.schlick.zeroF0Coefficients } }),
      f0table: () => ({ material: { name: "f0_table_probe", basis: config.f0Table.basis, coefficients: config.f0Table.coefficients[0], coat: null },
                      f0Table: { coefficients: config.f0Table.coefficients } }),
      [config.f0TableCoated.name]: () => coatedTable,
    };
    const source = sources[render.source] ? await sources[render.source]() : { material: materials[render.source] };
    const material = useMatcFresnel(new PBRMaterial("matc", scene), build, source, { areaLights: render.areaLights });
    material.roughness = render.roughness;
    // The Schlick and F0-table metals' F0 is the albedo colour (linear); the others' colour is in
    // their coefficients.
    material.albedoColor.set(...(render.source === "schlick" ? config.schlick.color
                                 : tableColour(render.source) ? config.f0Table.color : [1, 1, 1]));
    made.push(material);
    out.renders[render.key] = await renderBabylonProbe({ scene, camera, material, light: render.light, config,
                                                         size: ${kProbeSize}, out, key: render.key });
    for (const thing of made) thing.dispose();
  }
  const original = ShaderStore.IncludesShadersStore.lightFragment;
  await checkBadInputs(out, {
    loadMatcBuild: (url) => loadMatcBuild(url, scene), build: directoryBuild, material: materials.beryllium,
    coated: materials[config.coated], filmed: materials[config.filmed],
    texture: constant(scene, [1, 1, 1]),
    useMatc: (source, options) => useMatcFresnel(new PBRMaterial("refused", scene), build, source, options),
    changeEngine: () => {
      ShaderStore.IncludesShadersStore.lightFragment =
          original.replaceAll("fresnelSchlickGGX(preInfo.VdotH,", "fresnelSchlickGGX(saturate(preInfo.VdotH),");
      return () => { ShaderStore.IncludesShadersStore.lightFragment = original; };
    } });
`,
});

const babylonVersion = () => JSON.parse(readFileSync(join(dirname(fileURLToPath(import.meta.url)), "node_modules",
                                                          "@babylonjs", "core", "package.json"), "utf8")).version;

await runProbeCheck({
  name: "Babylon.js", label: `Babylon.js ${babylonVersion()} PBRMaterial`, page: kPage, ...kBabylonProbeTerms,
}, process.argv.slice(2));
