// three.js's MeshPhysicalMaterial with matc's Fresnel (examples/web/three) and the stock one
// (F0 = the material's F0, Schlick's Fresnel), both against the project's Monte-Carlo reference of
// the same scene (tests/js/engine-scene.mjs: a sphere under an environment map, a point light and
// a rect area light), rendered by WebGLRenderer in headless Chromium for the Figure 2 material,
// beryllium and the textured inlay (through the coefficient table and its bake); the regions and
// what each must show are in tests/js/engine-reference.mjs.
//   node check-three-reference.mjs MATC MATERIALS_DIR EXAMPLES_WEB_DIR MATC_EXAMPLE_MAPS
//        EXAMPLES_TEXTURED_DIR [--markdown] [--images DIR] [--size N] [--lights PATH] [--timing]
import { modulePage, threeVersion } from "./browser-page.mjs";
import { runReferenceComparison } from "./engine-reference.mjs";
import { environmentRadiance, environmentTexels } from "./engine-scene.mjs";

const kPage = (config) => modulePage(config, {
  head: `import * as THREE from "three";
import { RectAreaLightUniformsLib } from "three/addons/lights/RectAreaLightUniformsLib.js";
import { KTX2Loader } from "three/addons/loaders/KTX2Loader.js";
import { loadMatcBuild, useMatcFresnel } from "/web/three/matc-three.mjs";
${environmentRadiance.toString()}
${environmentTexels.toString()}
`,
  body: `
  const scene = config.scene;
  out.images = {};
  const renderer = new THREE.WebGLRenderer({ canvas: document.createElement("canvas") });
  renderer.debug.onShaderError = (gl, program, vertex, fragment) =>
    out.errors.push(gl.getShaderInfoLog(fragment) || gl.getShaderInfoLog(vertex) || gl.getProgramInfoLog(program));
  renderer.setClearColor(0x000000, 0);
  RectAreaLightUniformsLib.init();
  const build = await loadMatcBuild("/out/");
  const size = scene.size;
  const target = new THREE.WebGLRenderTarget(size, size, { type: THREE.FloatType });
  const camera = new THREE.PerspectiveCamera(scene.camera.fov, 1, scene.camera.near, scene.camera.far);
  camera.position.set(...scene.camera.position);
  camera.lookAt(0, 0, 0);
  const equirect = new THREE.DataTexture(environmentTexels(scene.environment.width, scene.environment.height, scene.environment.intensity),
                                         scene.environment.width, scene.environment.height,
                                         THREE.RGBAFormat, THREE.FloatType);
  equirect.mapping = THREE.EquirectangularReflectionMapping;
  equirect.magFilter = equirect.minFilter = THREE.LinearFilter;
  equirect.wrapS = THREE.RepeatWrapping;
  equirect.needsUpdate = true;
  const environment = new THREE.PMREMGenerator(renderer).fromEquirectangular(equirect).texture;
  const sphere = new THREE.SphereGeometry(1, 256, 128);
  const lights = () => {
    const point = new THREE.PointLight(0xffffff, scene.point.intensity, 0, 2);
    point.position.set(...scene.point.position);
    const rect = new THREE.RectAreaLight(0xffffff, scene.rect.intensity, scene.rect.width, scene.rect.height);
    rect.position.set(...scene.rect.position);
    rect.lookAt(0, 0, 0);
    return [point, rect];
  };
  const draw = (key, material, withLights) => {
    const world = new THREE.Scene();
    world.add(new THREE.Mesh(sphere, material));
    if (withLights) {
      world.environment = environment;
      world.add(...lights());
    }
    renderer.setRenderTarget(target);
    renderer.render(world, camera);  // compiles
    const pixels = new Float32Array(size * size * 4);
    renderer.readRenderTargetPixels(target, 0, 0, size, size, pixels);
    out.images[key] = base64Floats(pixels);
    // Frame time (--timing): the same frame drawn again, finished by reading a pixel back; timed
    // from outside, as the page's clock is virtual.
    if (withLights && config.timing?.kind && key.endsWith(config.timing.kind)) {
      out.timedDraws = (out.timedDraws ?? 0) + 1;
      for (let i = 0; i < config.timing.frames; ++i) renderer.render(world, camera);
      renderer.readRenderTargetPixels(target, 0, 0, 1, 1, new Float32Array(4));
    }
  };
  const references = (material) => ({
      reference_environment: { value: equirect }, reference_albedo: { value: build.lut },
      reference_roughness: { value: material.roughness },
      reference_point_position: { value: new THREE.Vector3(...scene.point.position) },
      reference_point_intensity: { value: scene.point.intensity },
      reference_rect_origin: { value: new THREE.Vector3(...config.rect.origin) },
      reference_rect_u: { value: new THREE.Vector3(...config.rect.edgeU) },
      reference_rect_v: { value: new THREE.Vector3(...config.rect.edgeV) },
      reference_rect_normal: { value: new THREE.Vector3(...config.rect.normal) },
      reference_rect_intensity: { value: scene.rect.intensity },
      reference_environment_samples: { value: scene.samples.environment },
      reference_rect_side: { value: scene.samples.rectSide },
      reference_lut_size: { value: build.lut.image.width },
      reference_textured: { value: 0 }, reference_f0: { value: new THREE.Vector3() },
  });
  const referenceMaterial = (uniforms) => new THREE.ShaderMaterial({
      glslVersion: THREE.GLSL3, uniforms, vertexShader: config.vertexShader, fragmentShader: config.fragmentShader,
      defines: { REFERENCE_GEOMETRY_ROUGHNESS: "" } });  // three.js widens roughness by the normal's derivative
  if (config.textured) {
    // The inlay: its sRGB maps (rows as stored, like the bake's KTX2 files), the bake's textures
    // sampled trilinearly.
    const textured = config.textured;
    const loader = new THREE.TextureLoader();
    const map = async (url) => {
      const texture = await loader.loadAsync(url);
      texture.colorSpace = THREE.SRGBColorSpace;
      texture.flipY = false;
      return texture;
    };
    const reflectivity = await map("/textured/maps/inlaid_metals_r.png");
    const edgeTint = await map("/textured/maps/inlaid_metals_g.png");
    const ktx2 = new KTX2Loader().detectSupport(renderer);
    const baked = async (file) => ktx2.loadAsync("/textured/baked/" + file);
    const uniforms = { ...references(textured), reference_textured: { value: 1 },
                       reference_reflectivity_map: { value: reflectivity }, reference_edge_tint_map: { value: edgeTint } };
    if (!config.timing) draw(textured.name + " reference", referenceMaterial(uniforms), false);
    draw(textured.name + " stock", new THREE.MeshPhysicalMaterial({ metalness: 1, roughness: textured.roughness,
                                                                    map: reflectivity }), true);
    draw(textured.name + " matc", useMatcFresnel(new THREE.MeshPhysicalMaterial({ roughness: textured.roughness }),
                                                 build, { reflectivityMap: reflectivity, edgeTintMap: edgeTint }), true);
    draw(textured.name + " baked", useMatcFresnel(new THREE.MeshPhysicalMaterial({ roughness: textured.roughness }),
        build, { baked: { c2Map: await baked("inlaid_metals_c2.ktx2"), c3Map: await baked("inlaid_metals_c3.ktx2"),
                          f0Map: await baked("inlaid_metals_f0.ktx2") } }), true);
  }
  for (const material of config.materials) {
    const fresnel = new THREE.DataTexture(new Float32Array(material.exactFresnel), material.exactFresnel.length / 4, 1,
                                          THREE.RGBAFormat, THREE.FloatType);
    fresnel.magFilter = fresnel.minFilter = THREE.LinearFilter;
    fresnel.needsUpdate = true;
    const uniforms = { ...references(material), reference_fresnel: { value: fresnel },
                       reference_f0: { value: new THREE.Vector3(...material.f0) } };
    if (!config.timing) draw(material.name + " reference", referenceMaterial(uniforms), false);
    const stock = new THREE.MeshPhysicalMaterial({ metalness: 1, roughness: material.roughness,
      color: new THREE.Color().setRGB(...material.f0, THREE.LinearSRGBColorSpace) });
    draw(material.name + " stock", stock, true);
    const ours = useMatcFresnel(new THREE.MeshPhysicalMaterial({ roughness: material.roughness }), build,
                                { material: await build.loadMaterial(material.name) });
    draw(material.name + " matc", ours, true);
    const engineLtc = useMatcFresnel(new THREE.MeshPhysicalMaterial({ roughness: material.roughness }), build,
                                     { material: await build.loadMaterial(material.name) }, { areaLights: "engine" });
    draw(material.name + " matc-engine-ltc", engineLtc, true);
  }
`,
});


await runReferenceComparison({ name: "three.js", prefix: "three", page: kPage,
                               label: `three.js ${threeVersion()} (WebGLRenderer, ANGLE on SwiftShader)` },
                             process.argv.slice(2));
