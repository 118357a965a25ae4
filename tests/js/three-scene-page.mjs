// In-page helpers (served under /checks/) for the three.js pages: the scene of engine-scene.mjs in
// three.js objects, its Monte-Carlo reference as a WebGLRenderer ShaderMaterial, the probe checks'
// plane scene, and a WebGPURenderer on headless Chromium's adapter. check-three-reference.mjs
// draws everything with WebGLRenderer; check-three-webgpu-reference.mjs draws the reference with
// WebGLRenderer and the engine's materials with WebGPURenderer. THREE is either namespace ("three"
// or "three/webgpu": one core).
import { environmentTexels, kReferenceFragmentShader, kReferenceVertexShader, rectLightGeometry } from "./engine-scene.mjs";

// A WebGPURenderer on the page's own device (three's adapter request, featureLevel
// "compatibility", does not settle on headless Chromium's SwiftShader adapter), with three's LTC
// tables for rect lights (ltcTables: RectAreaLightTexturesLib). THREE: "three/webgpu".
export async function webGpuRenderer(THREE, ltcTables) {
  if (!navigator.gpu) throw new Error("no WebGPU in this browser");
  const adapter = await navigator.gpu.requestAdapter();
  const device = await adapter.requestDevice({
    requiredFeatures: [...adapter.features].filter((feature) => feature === "float32-filterable") });
  const renderer = new THREE.WebGPURenderer({ canvas: document.createElement("canvas"), device });
  await renderer.init();
  if (!renderer.backend.isWebGPUBackend) throw new Error("WebGPURenderer fell back to WebGL2");
  THREE.RectAreaLightNode.setLTC(ltcTables.init());
  return renderer;
}

// The scenes' lights as three.js places them: a point light ({ position, intensity }, inverse-square
// falloff) and a rect light ({ position, width, height, intensity }) looking at the origin.
export function pointLight(THREE, { position, intensity }) {
  const light = new THREE.PointLight(0xffffff, intensity, 0, 2);
  light.position.set(...position);
  return light;
}

export function rectLight(THREE, { position, width, height, intensity }) {
  const light = new THREE.RectAreaLight(0xffffff, intensity, width, height);
  light.position.set(...position);
  light.lookAt(0, 0, 0);
  return light;
}

// The probe checks' target, camera (a 90 degree view of the plane z = 0 from z = 1) and white
// environment (PMREM of a constant) for a WebGLRenderer; the caller disposes the target and pmrem.
export function probeSetup(THREE, renderer, size) {
  const target = new THREE.WebGLRenderTarget(size, size, { type: THREE.FloatType });
  const camera = new THREE.PerspectiveCamera(90, 1, 0.1, 10);
  camera.position.set(0, 0, 1);
  const pmrem = new THREE.PMREMGenerator(renderer);
  const white = new THREE.DataTexture(new Float32Array(64 * 32 * 4).fill(1), 64, 32, THREE.RGBAFormat, THREE.FloatType);
  white.mapping = THREE.EquirectangularReflectionMapping;
  white.needsUpdate = true;
  return { target, camera, pmrem, environment: pmrem.fromEquirectangular(white).texture };
}

// Renders `scene` into the probe target and reads the RGB of each of `pixels` ([x, y], y up).
export function renderProbePixels(renderer, scene, camera, target, pixels) {
  renderer.setRenderTarget(target);
  renderer.render(scene, camera);
  return pixels.map(([x, y]) => {
    const texel = new Float32Array(4);
    renderer.readRenderTargetPixels(target, x, y, 1, 1, texel);
    return Array.from(texel.subarray(0, 3));
  });
}

// The same for a WebGPURenderer: the target, the camera, the white environment (an equirectangular
// texture, which the renderer prefilters itself), and renderPixels(scene, pixels): the RGB of each
// of `pixels` ([x, y], y up; WebGPU reads rows from the top).
export function webGpuProbeSetup(THREE, renderer, size) {
  const target = new THREE.RenderTarget(size, size, { type: THREE.FloatType });
  const camera = new THREE.PerspectiveCamera(90, 1, 0.1, 10);
  camera.position.set(0, 0, 1);
  const environment = new THREE.DataTexture(new Float32Array(64 * 32 * 4).fill(1), 64, 32, THREE.RGBAFormat, THREE.FloatType);
  environment.mapping = THREE.EquirectangularReflectionMapping;
  environment.needsUpdate = true;
  const renderPixels = async (scene, pixels) => {
    renderer.setRenderTarget(target);
    renderer.render(scene, camera);
    const rgb = [];
    for (const [x, y] of pixels) {
      const texel = await renderer.readRenderTargetPixelsAsync(target, x, size - 1 - y, 1, 1);
      rgb.push(Array.from(texel.subarray(0, 3)));
    }
    return rgb;
  };
  return { target, camera, environment, renderPixels };
}

// The probe checks' scene (engine-probes.mjs): a plane with `material` under one render's light
// ("environment": `environment`; "point", "rect": config's lights).
export function probeScene(THREE, material, light, config, environment) {
  const scene = new THREE.Scene();
  scene.add(new THREE.Mesh(new THREE.PlaneGeometry(4, 4), material));
  if (light === "environment") scene.environment = environment;
  if (light === "point") scene.add(pointLight(THREE, config.point));
  if (light === "rect") scene.add(rectLight(THREE, config.rect));
  return scene;
}

// scene: the page config's scene (engine-scene.mjs's kScene with the light paths kept).
export function threeScene(THREE, scene) {
  const camera = new THREE.PerspectiveCamera(scene.camera.fov, 1, scene.camera.near, scene.camera.far);
  camera.position.set(...scene.camera.position);
  camera.lookAt(0, 0, 0);
  const { width, height, intensity } = scene.environment;
  const equirect = new THREE.DataTexture(environmentTexels(width, height, intensity), width, height,
                                         THREE.RGBAFormat, THREE.FloatType);
  equirect.mapping = THREE.EquirectangularReflectionMapping;
  equirect.magFilter = equirect.minFilter = THREE.LinearFilter;
  equirect.wrapS = THREE.RepeatWrapping;
  equirect.needsUpdate = true;
  const sphere = new THREE.SphereGeometry(1, 256, 128);
  const lights = () => [pointLight(THREE, scene.point), rectLight(THREE, scene.rect)];
  return { camera, equirect, sphere, lights };
}

// The reference's ShaderMaterial (WebGLRenderer) for `material` ({ roughness, f0, exactFresnel:
// the curves' two rows, coatRoughness for a coated metal } or the inlay's { roughness } with its
// maps); lut: matc_lut as a texture (channel 0: the lobe's albedo, for the multiple-scattering
// factor).
export function referenceMaterial(THREE, scene, equirect, lut, material, maps = null) {
  const rect = rectLightGeometry(scene.rect);
  const vector = (v) => new THREE.Vector3(...v);
  const uniforms = {
    reference_environment: { value: equirect }, reference_albedo: { value: lut },
    reference_roughness: { value: material.roughness },
    reference_point_position: { value: vector(scene.point.position) },
    reference_point_intensity: { value: scene.point.intensity },
    reference_rect_origin: { value: vector(rect.origin) }, reference_rect_u: { value: vector(rect.edgeU) },
    reference_rect_v: { value: vector(rect.edgeV) }, reference_rect_normal: { value: vector(rect.normal) },
    reference_rect_intensity: { value: scene.rect.intensity },
    reference_environment_samples: { value: scene.samples.environment },
    reference_rect_side: { value: scene.samples.rectSide },
    reference_lut_size: { value: lut.image.height },
    reference_lut_layers: { value: lut.image.width / lut.image.height },
    reference_textured: { value: maps ? 1 : 0 }, reference_f0: { value: vector(material.f0 ?? [0, 0, 0]) },
    reference_coated: { value: material.coatRoughness === undefined ? 0 : 1 },
    reference_coat_roughness: { value: material.coatRoughness ?? 0 },
  };
  if (maps) {
    uniforms.reference_reflectivity_map = { value: maps.reflectivity };
    uniforms.reference_edge_tint_map = { value: maps.edgeTint };
  } else {
    const fresnel = new THREE.DataTexture(new Float32Array(material.exactFresnel), material.exactFresnel.length / 8, 2,
                                          THREE.RGBAFormat, THREE.FloatType);
    fresnel.magFilter = fresnel.minFilter = THREE.LinearFilter;
    fresnel.needsUpdate = true;
    uniforms.reference_fresnel = { value: fresnel };
  }
  // three.js widens roughness by the normal's derivative: the reference shades with it too.
  return new THREE.ShaderMaterial({ glslVersion: THREE.GLSL3, uniforms, vertexShader: kReferenceVertexShader,
                                    fragmentShader: kReferenceFragmentShader,
                                    defines: { REFERENCE_GEOMETRY_ROUGHNESS: "" } });
}

// The inlay's sRGB maps (rows as stored, like the bake's KTX2 files).
export async function inlayMaps(THREE) {
  const loader = new THREE.TextureLoader();
  const map = async (url) => {
    const texture = await loader.loadAsync(url);
    texture.colorSpace = THREE.SRGBColorSpace;
    texture.flipY = false;
    return texture;
  };
  return { reflectivity: await map("/textured/maps/inlaid_metals_r.png"),
           edgeTint: await map("/textured/maps/inlaid_metals_g.png") };
}
