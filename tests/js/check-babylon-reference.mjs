// Babylon.js's PBRMaterial with matc's Fresnel (js/package/babylon) and the stock one (metallic
// 1, albedo = the material's F0, Schlick's Fresnel), both against the project's Monte-Carlo
// reference of the same scene (tests/js/engine-scene.mjs) run as a Babylon ShaderMaterial, in
// headless Chromium (Babylon's WebGL2 engine), for the Figure 2 material, beryllium and the
// textured inlay (through the coefficient table and its bake), and the coated car paint of
// examples/gltf as Babylon's glTF loader builds it and as matc's loader extension does; the
// regions and what each must show are in tests/js/engine-reference.mjs. The environment is a float cube map prefiltered by
// Babylon's own HDRFiltering, which the reference samples at its base level. Babylon loads its
// area lights' LTC tables from its CDN at run time; with no network here, the page points
// Tools.AssetBaseUrl at a local copy of Heitz et al.'s tables (three.js's RectAreaLightTexturesLib,
// the fit and layout Babylon ships) written in Babylon's file format.
//   node check-babylon-reference.mjs MATC MATERIALS_DIR EXAMPLES_WEB_DIR MATC_EXAMPLE_MAPS
//        EXAMPLES_TEXTURED_DIR [--markdown] [--images DIR] [--size N] [--lights PATH] [--timing]
import { mkdirSync, readFileSync, writeFileSync } from "node:fs";
import { dirname, join } from "node:path";
import { fileURLToPath } from "node:url";
import { RectAreaLightTexturesLib } from "three/addons/lights/RectAreaLightTexturesLib.js";
import { modulePage } from "./browser-page.mjs";
import { runReferenceComparison } from "./engine-reference.mjs";
import { environmentCubeFaces, environmentRadiance } from "./engine-scene.mjs";

const kBabylonPrelude = "precision highp float;\n#define REFERENCE_CUBE_ENVIRONMENT\n#define REFERENCE_GL_FRAG_COLOR\nuniform vec3 cameraPosition;\nuniform mat4 viewMatrix;\n";
const kBabylonVertexShader = `precision highp float;
attribute vec3 position;
attribute vec3 normal;
attribute vec2 uv;
uniform mat4 world;
uniform mat4 viewProjection;
varying vec3 reference_position;
varying vec3 reference_normal;
varying vec2 reference_uv;
void main() {
  vec4 p = world * vec4(position, 1.0);
  reference_position = p.xyz;
  reference_normal = normalize(mat3(world) * normal);
  reference_uv = uv;
  gl_Position = viewProjection * p;
}`;

const kPage = (config) => modulePage(config, {
  head: `import "@babylonjs/loaders/glTF/2.0/index.js";
import { LoadAssetContainerAsync } from "@babylonjs/core/Loading/sceneLoader.js";
import { Constants } from "@babylonjs/core/Engines/constants.js";
import { Matrix, Quaternion, Vector3 } from "@babylonjs/core/Maths/math.vector.js";
import { Color3, Color4 } from "@babylonjs/core/Maths/math.color.js";
import { CreateSphere } from "@babylonjs/core/Meshes/Builders/sphereBuilder.js";
import { TransformNode } from "@babylonjs/core/Meshes/transformNode.js";
import { PBRMaterial } from "@babylonjs/core/Materials/PBR/pbrMaterial.js";
import { ShaderMaterial } from "@babylonjs/core/Materials/shaderMaterial.js";
import { PointLight } from "@babylonjs/core/Lights/pointLight.js";
import { RectAreaLight } from "@babylonjs/core/Lights/rectAreaLight.js";
import { RawTexture } from "@babylonjs/core/Materials/Textures/rawTexture.js";
import { RawCubeTexture } from "@babylonjs/core/Materials/Textures/rawCubeTexture.js";
import { Texture } from "@babylonjs/core/Materials/Textures/texture.js";
import { RenderTargetTexture } from "@babylonjs/core/Materials/Textures/renderTargetTexture.js";
import { HDRFiltering } from "@babylonjs/core/Materials/Textures/Filtering/hdrFiltering.js";
import { CubeMapToSphericalPolynomialTools } from "@babylonjs/core/Misc/HighDynamicRange/cubemapToSphericalPolynomial.js";
import { Tools } from "@babylonjs/core/Misc/tools.js";
import { read as readKtx2 } from "ktx-parse";
import { loadMatcBuild, useMatcFresnel } from "/web/babylon/matc-babylon.mjs";
import { registerMatcGltfExtension } from "/web/babylon/matc-gltf.mjs";
import { babylonProbeScene } from "/checks/babylon-scene-page.mjs";
${environmentRadiance.toString()}
${environmentCubeFaces.toString()}
`,
  body: `
  const sceneConfig = config.scene;
  const size = sceneConfig.size;
  out.images = {};
  Tools.AssetBaseUrl = location.origin + "/babylon-assets";
  const { engine, scene, camera } = babylonProbeScene(size, sceneConfig.camera);
  const build = await loadMatcBuild("/out/", scene);
  // The environment: a float cube map with mips, prefiltered by Babylon, and its irradiance.
  const faceSize = 128;
  const faces = environmentCubeFaces(faceSize, sceneConfig.environment.intensity, true);
  const environment = new RawCubeTexture(scene, faces, faceSize, Constants.TEXTUREFORMAT_RGBA,
                                         Constants.TEXTURETYPE_FLOAT, true, false, Constants.TEXTURE_TRILINEAR_SAMPLINGMODE);
  environment.gammaSpace = false;
  await new HDRFiltering(engine).prefilter(environment);
  environment.sphericalPolynomial = CubeMapToSphericalPolynomialTools.ConvertCubeMapToSphericalPolynomial({
    size: faceSize, right: faces[0], left: faces[1], up: faces[2], down: faces[3], front: faces[4], back: faces[5],
    format: Constants.TEXTUREFORMAT_RGBA, type: Constants.TEXTURETYPE_FLOAT, gammaSpace: false });
  // The unfiltered environment for the reference.
  const unfiltered = new RawCubeTexture(scene, environmentCubeFaces(faceSize, sceneConfig.environment.intensity, true),
                                        faceSize, Constants.TEXTUREFORMAT_RGBA, Constants.TEXTURETYPE_FLOAT, false, false,
                                        Constants.TEXTURE_BILINEAR_SAMPLINGMODE);
  const sphere = CreateSphere("sphere", { diameter: 2, segments: 128 }, scene);
  // The lights: the point light, and the rect light on a node whose axes are the light's
  // (x along its width, y along its height, z away from the origin: it lights towards -z).
  const lights = [];
  const point = new PointLight("point", new Vector3(...sceneConfig.point.position), scene);
  point.intensity = sceneConfig.point.intensity;
  point.radius = 0;
  point.specular = new Color3(1, 1, 1);
  const node = new TransformNode("rect-frame", scene);
  node.position = new Vector3(...sceneConfig.rect.position);
  const [ux, uy, uz] = [config.rect.edgeU, config.rect.edgeV, config.rect.normal.map((v) => -v)]
      .map((axis) => { const v = new Vector3(...axis); return v.normalize(); });
  node.rotationQuaternion = Quaternion.FromRotationMatrix(Matrix.FromXYZAxesToRef(ux, uy, uz, new Matrix()));
  // Babylon's stock area-light Fresnel only works for light colours up to 1: a light of radiance
  // n is n coincident lights of radiance 1 (engine-scene.mjs).
  const rects = Array.from({ length: Math.round(sceneConfig.rect.intensity) }, (_, i) => {
    const rect = new RectAreaLight("rect" + i, Vector3.Zero(), sceneConfig.rect.width, sceneConfig.rect.height, scene);
    rect.parent = node;
    rect.intensity = 1;
    rect.specular = new Color3(1, 1, 1);
    return rect;
  });
  const target = new RenderTargetTexture("frame", size, scene, { type: Constants.TEXTURETYPE_FLOAT, generateMipMaps: false });
  target.activeCamera = camera;
  target.renderList = [sphere];
  target.clearColor = new Color4(0, 0, 0, 0);
  const draw = async (key, material, withLights) => {
    sphere.material = material;
    scene.environmentTexture = withLights ? environment : null;
    point.setEnabled(withLights);
    for (const rect of rects) rect.setEnabled(withLights);
    await scene.whenReadyAsync();
    for (let attempt = 0; attempt < 100 && !material.isReady(sphere); ++attempt) {
      scene.render();
      await new Promise((resolve) => setTimeout(resolve, 20));
    }
    if (!material.isReady(sphere)) out.errors.push(key + ": the material never became ready");
    target.render();
    target.render();
    out.images[key] = base64Floats(await target.readPixels());
    // Frame time (--timing, run in real time): the same frame drawn again, from an idle GPU
    // process to a pixel read back.
    if (withLights && config.timing?.kind && key.endsWith(config.timing.kind)) {
      const finish = () => target.readPixels(0, 0, null, true, false, 0, 0, 1, 1);
      await finish();
      const start = performance.now();
      for (let i = 0; i < config.timing.frames; ++i) target.render();
      await finish();
      (out.frameTimes ??= []).push((performance.now() - start) / config.timing.frames);
    }
  };
  const referenceMaterial = (material, textured) => {
    const uniforms = ["world", "viewProjection", "cameraPosition", "viewMatrix", "reference_roughness",
      "reference_f0", "reference_point_position", "reference_point_intensity", "reference_rect_origin",
      "reference_rect_u", "reference_rect_v", "reference_rect_normal", "reference_rect_intensity",
      "reference_environment_samples", "reference_rect_side", "reference_lut_size", "reference_lut_layers", "reference_textured",
      "reference_coated", "reference_coat_roughness"];
    const shader = new ShaderMaterial("reference", scene, { vertexSource: config.babylonVertexShader,
      fragmentSource: config.fragmentPrelude + config.fragmentShader },
      { attributes: ["position", "normal", "uv"], uniforms,
        samplers: ["reference_environment", "reference_fresnel", "reference_albedo",
                   "reference_reflectivity_map", "reference_edge_tint_map"] });
    shader.setVector3("cameraPosition", camera.position);
    shader.setMatrix("viewMatrix", camera.getViewMatrix());
    shader.setFloat("reference_roughness", material.roughness);
    shader.setVector3("reference_f0", new Vector3(...(material.f0 ?? [0, 0, 0])));
    shader.setVector3("reference_point_position", new Vector3(...sceneConfig.point.position));
    shader.setFloat("reference_point_intensity", sceneConfig.point.intensity);
    shader.setVector3("reference_rect_origin", new Vector3(...config.rect.origin));
    shader.setVector3("reference_rect_u", new Vector3(...config.rect.edgeU));
    shader.setVector3("reference_rect_v", new Vector3(...config.rect.edgeV));
    shader.setVector3("reference_rect_normal", new Vector3(...config.rect.normal));
    shader.setFloat("reference_rect_intensity", sceneConfig.rect.intensity);
    shader.setInt("reference_environment_samples", sceneConfig.samples.environment);
    shader.setInt("reference_rect_side", sceneConfig.samples.rectSide);
    shader.setFloat("reference_lut_size", build.lut.getSize().height);
    shader.setFloat("reference_lut_layers", build.lut.getSize().width / build.lut.getSize().height);
    shader.setInt("reference_textured", textured ? 1 : 0);
    shader.setInt("reference_coated", material.coatRoughness === undefined ? 0 : 1);
    shader.setFloat("reference_coat_roughness", material.coatRoughness ?? 0);
    shader.setTexture("reference_environment", unfiltered);
    shader.setTexture("reference_albedo", build.lut);
    if (material.exactFresnel) {
      shader.setTexture("reference_fresnel", new RawTexture(new Float32Array(material.exactFresnel),
          material.exactFresnel.length / 8, 2, Constants.TEXTUREFORMAT_RGBA, scene, false, false,
          Constants.TEXTURE_BILINEAR_SAMPLINGMODE, Constants.TEXTURETYPE_FLOAT));
    } else {
      shader.setTexture("reference_fresnel", build.lut);  // unused by the textured branch
    }
    if (textured) {
      shader.setTexture("reference_reflectivity_map", textured.reflectivity);
      shader.setTexture("reference_edge_tint_map", textured.edgeTint);
    }
    shader.backFaceCulling = true;
    return shader;
  };
  if (config.textured) {
    // The inlay: its sRGB maps (rows as stored, like the bake's KTX2 files, which are read here
    // with ktx-parse), sampled trilinearly.
    const textured = config.textured;
    // matc's maps and the reference read linear values (an sRGB texture format decodes them); the
    // stock material's albedo map is Babylon's usual gamma-space texture.
    const map = (url, srgbBuffer) => new Promise((resolve, reject) => {
      const texture = new Texture(url, scene, { noMipmap: false, invertY: false, useSRGBBuffer: srgbBuffer,
                                                samplingMode: Texture.TRILINEAR_SAMPLINGMODE,
                                                onLoad: () => resolve(texture),
                                                onError: (message) => reject(new Error(url + ": " + message)) });
      texture.gammaSpace = !srgbBuffer;
    });
    const reflectivity = await map("/textured/maps/inlaid_metals_r.png", true);
    const edgeTint = await map("/textured/maps/inlaid_metals_g.png", true);
    const albedo = await map("/textured/maps/inlaid_metals_r.png", false);
    const baked = async (file) => {
      const container = readKtx2(new Uint8Array(await (await fetch("/textured/baked/" + file)).arrayBuffer()));
      const level = container.levels[0].levelData;
      const texture = new RawTexture(new Uint16Array(level.buffer.slice(level.byteOffset, level.byteOffset + level.byteLength)),
                                     container.pixelWidth, container.pixelHeight, Constants.TEXTUREFORMAT_RGBA, scene, false,
                                     false, Constants.TEXTURE_BILINEAR_SAMPLINGMODE, Constants.TEXTURETYPE_HALF_FLOAT);
      // The bake's mip chain, level by level.
      const internal = texture.getInternalTexture();
      engine._bindTextureDirectly(engine._gl.TEXTURE_2D, internal, true);
      for (let i = 1; i < container.levels.length; ++i) {
        const data = container.levels[i].levelData;
        engine._uploadDataToTextureDirectly(internal,
            new Uint16Array(data.buffer.slice(data.byteOffset, data.byteOffset + data.byteLength)), 0, i);
      }
      engine._bindTextureDirectly(engine._gl.TEXTURE_2D, null);
      texture.getInternalTexture().generateMipMaps = true;
      texture.updateSamplingMode(Constants.TEXTURE_TRILINEAR_SAMPLINGMODE);
      return texture;
    };
    if (!config.timing) await draw(textured.name + " reference", referenceMaterial(textured, { reflectivity, edgeTint }), false);
    const stock = new PBRMaterial("stock", scene);
    stock.metallic = 1;
    stock.roughness = textured.roughness;
    stock.albedoTexture = albedo;
    await draw(textured.name + " stock", stock, true);
    const table = useMatcFresnel(new PBRMaterial("table", scene), build, { reflectivityMap: reflectivity, edgeTintMap: edgeTint });
    table.roughness = textured.roughness;
    await draw(textured.name + " matc", table, true);
    const bakedMaterial = useMatcFresnel(new PBRMaterial("baked", scene), build, { baked: {
      c2Map: await baked("inlaid_metals_c2.ktx2"), c3Map: await baked("inlaid_metals_c3.ktx2"),
      f0Map: await baked("inlaid_metals_f0.ktx2") } });
    bakedMaterial.roughness = textured.roughness;
    await draw(textured.name + " baked", bakedMaterial, true);
  }
  for (const material of config.materials) {
    if (!config.timing) await draw(material.name + " reference", referenceMaterial(material, null), false);
    const stock = new PBRMaterial("stock", scene);
    stock.metallic = 1;
    stock.roughness = material.roughness;
    stock.albedoColor = new Color3(...material.f0);
    await draw(material.name + " stock", stock, true);
    const ours = useMatcFresnel(new PBRMaterial("matc", scene), build, { material: await build.loadMaterial(material.name) });
    ours.roughness = material.roughness;
    await draw(material.name + " matc", ours, true);
    const engineLtc = useMatcFresnel(new PBRMaterial("matc-engine-ltc", scene), build,
                                     { material: await build.loadMaterial(material.name) }, { areaLights: "engine" });
    engineLtc.roughness = material.roughness;
    await draw(material.name + " matc-engine-ltc", engineLtc, true);
    const quality = useMatcFresnel(new PBRMaterial("matc-quality", scene), build,
                                   { material: await build.loadMaterial(material.name) }, { areaLights: "quality" });
    quality.roughness = material.roughness;
    await draw(material.name + " matc-quality", quality, true);
  }
  if (config.coated && !config.timing) {
    // The car paint as Babylon's glTF loader builds it, and as matc's loader extension does.
    const coated = config.coated;
    const loaded = async (options) => {
      const registration = options ? registerMatcGltfExtension(options) : null;
      try {
        const container = await LoadAssetContainerAsync(coated.asset, scene);
        // Babylon's glTF loader turns on its specular anti-aliasing (roughness widened by the
        // normal's derivatives), which the reference does not model (unlike three.js's, which it
        // does): off in both loads, so that what differs is the Fresnel and the layering.
        const material = container.materials[0];
        material.enableSpecularAntiAliasing = false;
        return { material, made: registration?.materials ?? [] };
      } finally {
        registration?.unregister();
      }
    };
    await draw(coated.name + " reference", referenceMaterial(coated, null), false);
    await draw(coated.name + " stock", (await loaded(null)).material, true);
    const ours = await loaded({ build });
    if (ours.made.length !== 1 || ours.material.metadata?.matc?.from !== "extension") {
      out.errors.push(coated.asset + ": matc's loader extension did not make the car paint a matc metal from its extension");
    }
    await draw(coated.name + " matc", ours.material, true);
  }
`,
});

// Heitz et al.'s LTC tables in Babylon's areaLightsLTC.bin layout (per texel: LTC1 then LTC2,
// half floats), from three.js's copy.
function writeBabylonLtcTables(dir) {
  RectAreaLightTexturesLib.init();
  const one = RectAreaLightTexturesLib.LTC_HALF_1.image.data, two = RectAreaLightTexturesLib.LTC_HALF_2.image.data;
  const bin = new Uint16Array(one.length * 2);
  for (let texel = 0; texel < one.length / 4; ++texel) {
    bin.set(one.subarray(4 * texel, 4 * texel + 4), 8 * texel);
    bin.set(two.subarray(4 * texel, 4 * texel + 4), 8 * texel + 4);
  }
  const assets = join(dir, "babylon-assets");
  mkdirSync(join(assets, "areaLights"), { recursive: true });
  writeFileSync(join(assets, "areaLights", "areaLightsLTC.bin"), bin);
  return { "babylon-assets": assets };
}

const babylonVersion = JSON.parse(readFileSync(join(dirname(fileURLToPath(import.meta.url)), "node_modules",
                                                    "@babylonjs", "core", "package.json"), "utf8")).version;
await runReferenceComparison({
  name: "Babylon.js", prefix: "babylon", label: `Babylon.js ${babylonVersion} (WebGL2 engine, ANGLE on SwiftShader)`,
  page: (config) => kPage({ ...config, babylonVertexShader: kBabylonVertexShader, fragmentPrelude: kBabylonPrelude }),
  prepare: writeBabylonLtcTables, coated: true,
}, process.argv.slice(2));
