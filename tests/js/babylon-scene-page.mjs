// In-page helpers (served under /checks/) for the Babylon.js pages (check-babylon-engine.mjs,
// check-babylon-gltf.mjs, check-babylon-reference.mjs): a scene as the checks draw it
// (right-handed, linear output, a camera looking at the origin; by default the probe checks' 90
// degree view of the plane z = 0 from z = 1) and one probe render of a material on that plane under a
// white environment, a point light or a rect light (engine-probes.mjs has the CPU side).
import { Engine } from "@babylonjs/core/Engines/engine.js";
import { Constants } from "@babylonjs/core/Engines/constants.js";
import { Scene } from "@babylonjs/core/scene.js";
import { FreeCamera } from "@babylonjs/core/Cameras/freeCamera.js";
import { Vector3 } from "@babylonjs/core/Maths/math.vector.js";
import { Color4 } from "@babylonjs/core/Maths/math.color.js";
import { CubeMapToSphericalPolynomialTools } from "@babylonjs/core/Misc/HighDynamicRange/cubemapToSphericalPolynomial.js";
import { CreatePlane } from "@babylonjs/core/Meshes/Builders/planeBuilder.js";
import { PointLight } from "@babylonjs/core/Lights/pointLight.js";
import { RectAreaLight } from "@babylonjs/core/Lights/rectAreaLight.js";
import { RawCubeTexture } from "@babylonjs/core/Materials/Textures/rawCubeTexture.js";
import { RenderTargetTexture } from "@babylonjs/core/Materials/Textures/renderTargetTexture.js";

// The engine, scene and camera of a page whose targets are `size` texels square; `camera`: its
// position, vertical field of view in degrees and clip distances.
export function babylonProbeScene(size, camera = { position: [0, 0, 1], fov: 90, near: 0.1, far: 10 }) {
  const canvas = document.createElement("canvas");
  canvas.width = canvas.height = size;
  const engine = new Engine(canvas, false, { preserveDrawingBuffer: true });
  const scene = new Scene(engine);
  scene.useRightHandedSystem = true;
  scene.clearColor = new Color4(0, 0, 0, 0);
  scene.imageProcessingConfiguration.applyByPostProcess = true;  // linear output
  const view = new FreeCamera("camera", new Vector3(...camera.position), scene);
  view.setTarget(Vector3.Zero());
  view.fov = (camera.fov * Math.PI) / 180;
  view.minZ = camera.near;
  view.maxZ = camera.far;
  return { engine, scene, camera: view };
}

// `material` on the probe plane under `light` ("environment", "point": config.point, "rect":
// config.rect), rendered into a float target of `size` texels; the RGB at config.pixels. What it
// adds to the scene is disposed after; an error goes to out.errors under `key`.
export async function renderBabylonProbe({ scene, camera, material, light, config, size, out, key }) {
  const made = [];
  const plane = CreatePlane("plane", { size: 4, sideOrientation: 2 }, scene);
  plane.material = material;
  made.push(plane);
  if (light === "environment") {
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
  if (light === "point") {
    const point = new PointLight("point", new Vector3(...config.point.position), scene);
    point.intensity = config.point.intensity;
    point.radius = 0;
    point.specular.set(1, 1, 1);
    made.push(point);
  }
  if (light === "rect") {
    const rect = new RectAreaLight("rect", new Vector3(...config.rect.position), config.rect.width,
                                   config.rect.height, scene);
    rect.intensity = config.rect.intensity;
    rect.specular.set(1, 1, 1);
    made.push(rect);
  }
  const target = new RenderTargetTexture("probe", size, scene, { type: Constants.TEXTURETYPE_FLOAT,
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
  if (!material.isReadyForSubMesh(plane, plane.subMeshes[0])) out.errors.push(key + ": the material never became ready");
  target.render();  // twice: the first frame after a light is added may still compile
  target.render();
  const pixels = await target.readPixels();
  scene.environmentTexture = null;
  for (const thing of made) thing.dispose();
  return config.pixels.map(([x, y]) => Array.from(pixels.subarray(4 * (y * size + x), 4 * (y * size + x) + 3)));
}
