// matc's Fresnel inside Babylon.js's PBRMaterial (js/package/babylon/matc-babylon.mjs, a
// material plugin), rendered by Babylon's WebGL2 engine in headless Chromium into a float render
// target and compared, at probe pixels, with what the CPU runtime (`matc eval`) predicts, to 1e-4
// (relative above 1): under a white environment, a point light and a rect area light (also at the
// quality level, areaLights "quality"), for the Figure 2 material and beryllium, a textured metal
// through the coefficient table and a `matc bake` result (tests/js/engine-probes.mjs has the scene
// and the CPU side). Then the inputs that must fail, as for three.js, with a Babylon whose patched
// shader changed.
//   node check-babylon-engine.mjs MATC MATERIALS_DIR EXAMPLES_WEB_DIR
import { readFileSync } from "node:fs";
import { dirname, join } from "node:path";
import { fileURLToPath } from "node:url";
import { modulePage } from "./browser-page.mjs";
import { kProbeRectLight, kProbeSize, runProbeCheck } from "./engine-probes.mjs";

// Babylon's RectAreaLight: a centre, its width along world x and height along world y; it lights
// the side towards -z (Babylon's winding), here the plane below it.
const rectCorners = ({ position: [x, y, z], width, height }) => {
  const w = width / 2, h = height / 2;
  return [[x + w, y - h, z], [x - w, y - h, z], [x - w, y + h, z], [x + w, y + h, z]];
};

const kPage = (config) => modulePage(config, {
  head: `import { Engine } from "@babylonjs/core/Engines/engine.js";
import { Constants } from "@babylonjs/core/Engines/constants.js";
import { Scene } from "@babylonjs/core/scene.js";
import { FreeCamera } from "@babylonjs/core/Cameras/freeCamera.js";
import { Vector3 } from "@babylonjs/core/Maths/math.vector.js";
import { Color4 } from "@babylonjs/core/Maths/math.color.js";
import { CubeMapToSphericalPolynomialTools } from "@babylonjs/core/Misc/HighDynamicRange/cubemapToSphericalPolynomial.js";
import { CreatePlane } from "@babylonjs/core/Meshes/Builders/planeBuilder.js";
import { PBRMaterial } from "@babylonjs/core/Materials/PBR/pbrMaterial.js";
import { PointLight } from "@babylonjs/core/Lights/pointLight.js";
import { RectAreaLight } from "@babylonjs/core/Lights/rectAreaLight.js";
import { RawTexture } from "@babylonjs/core/Materials/Textures/rawTexture.js";
import { RawCubeTexture } from "@babylonjs/core/Materials/Textures/rawCubeTexture.js";
import { RenderTargetTexture } from "@babylonjs/core/Materials/Textures/renderTargetTexture.js";
import { ShaderStore } from "@babylonjs/core/Engines/shaderStore.js";
import { read as readKtx2 } from "ktx-parse";
import { probeBuild } from "/checks/page-probe-build.mjs";
import { loadMatcBuild, useMatcFresnel } from "/web/babylon/matc-babylon.mjs";
import { checkBadInputs, recordConsoleErrors } from "/checks/page-bad-inputs.mjs";
`,
  body: `
  out.renders = {};
  recordConsoleErrors(out);
  const canvas = document.createElement("canvas");
  canvas.width = canvas.height = ${kProbeSize};
  const engine = new Engine(canvas, false, { preserveDrawingBuffer: true });
  const scene = new Scene(engine);
  scene.useRightHandedSystem = true;
  scene.clearColor = new Color4(0, 0, 0, 0);
  scene.imageProcessingConfiguration.applyByPostProcess = true;  // linear output
  const camera = new FreeCamera("camera", new Vector3(0, 0, 1), scene);
  camera.setTarget(Vector3.Zero());
  camera.fov = Math.PI / 2;
  camera.minZ = 0.1;
  camera.maxZ = 10;
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
  for (const render of config.renders) {
    const made = [];  // what this render adds to the scene, disposed after it
    const sources = {
      textured: () => ({ reflectivityMap: constant(scene, config.textured.reflectivity),
                         edgeTintMap: constant(scene, config.textured.edgeTint) }),
      baked: async () => ({ baked: { c2Map: await baked(scene, "probe_c2.ktx2"), c3Map: await baked(scene, "probe_c3.ktx2"),
                                     f0Map: await baked(scene, "probe_f0.ktx2") } }),
    };
    const source = sources[render.source] ? await sources[render.source]() : { material: materials[render.source] };
    const material = useMatcFresnel(new PBRMaterial("matc", scene), build, source, { areaLights: render.areaLights });
    material.roughness = render.roughness;
    material.albedoColor.set(1, 1, 1);
    const plane = CreatePlane("plane", { size: 4, sideOrientation: 2 }, scene);
    plane.material = material;
    made.push(plane, material);
    if (render.light === "environment") {
      const face = new Float32Array(8 * 8 * 4).fill(1);
      const environment = new RawCubeTexture(scene, [face, face, face, face, face, face], 8,
                                             Constants.TEXTUREFORMAT_RGBA, Constants.TEXTURETYPE_FLOAT, false, false,
                                             Constants.TEXTURE_BILINEAR_SAMPLINGMODE);
      environment.gammaSpace = false;
      // Babylon mixes radiance with irradiance (MIX_IBL_RADIANCE_WITH_IRRADIANCE): the constant
      // environment's own spherical polynomial keeps both at 1.
      environment.sphericalPolynomial = CubeMapToSphericalPolynomialTools.ConvertCubeMapToSphericalPolynomial({
        size: 8, right: face, left: face, up: face, down: face, front: face, back: face,
        format: Constants.TEXTUREFORMAT_RGBA, type: Constants.TEXTURETYPE_FLOAT, gammaSpace: false });
      scene.environmentTexture = environment;
      made.push(environment);
    }
    if (render.light === "point") {
      const light = new PointLight("point", new Vector3(...config.point.position), scene);
      light.intensity = config.point.intensity;
      light.radius = 0;
      light.specular.set(1, 1, 1);
      made.push(light);
    }
    if (render.light === "rect") {
      const light = new RectAreaLight("rect", new Vector3(...config.rect.position), config.rect.width,
                                      config.rect.height, scene);
      light.intensity = config.rect.intensity;
      light.specular.set(1, 1, 1);
      made.push(light);
    }
    const target = new RenderTargetTexture("probe", ${kProbeSize}, scene, { type: Constants.TEXTURETYPE_FLOAT,
                                           generateMipMaps: false });
    target.activeCamera = camera;
    target.renderList = [plane];
    target.clearColor = new Color4(0, 0, 0, 0);
    made.push(target);
    await scene.whenReadyAsync();
    for (let attempt = 0; attempt < 50 && !material.isReadyForSubMesh(plane, plane.subMeshes[0]); ++attempt) {
      scene.render();
      await new Promise((resolve) => setTimeout(resolve, 20));
    }
    if (!material.isReadyForSubMesh(plane, plane.subMeshes[0])) out.errors.push(render.key + ": the material never became ready");
    target.render();  // twice: the first frame after a light is added may still compile
    target.render();
    const pixels = await target.readPixels();
    out.renders[render.key] = config.pixels.map(([x, y]) => Array.from(pixels.subarray(4 * (y * ${kProbeSize} + x), 4 * (y * ${kProbeSize} + x) + 3)));
    scene.environmentTexture = null;
    for (const thing of made) thing.dispose();
  }
  const original = ShaderStore.IncludesShadersStore.lightFragment;
  await checkBadInputs(out, {
    loadMatcBuild: (url) => loadMatcBuild(url, scene), build: directoryBuild, material: materials.beryllium,
    coated: materials[config.coated],
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
  name: "Babylon.js", label: `Babylon.js ${babylonVersion()} PBRMaterial`, page: kPage,
  alphaOf: (r) => r * r + 0.0005,  // Babylon's GGX alpha: roughness squared plus its minimum variance
  coatVisibility: "kelemen",  // Babylon's coat lobe: Kelemen's visibility (computeClearCoatLighting)
  // Babylon's energy conservation scales area lights' specular too.
  rect: { light: kProbeRectLight, corners: rectCorners(kProbeRectLight), compensated: true },
}, process.argv.slice(2));
