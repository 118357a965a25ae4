// three.js's MeshPhysicalMaterial with matc's Fresnel (js/package/three) and the stock one
// (F0 = the material's F0, Schlick's Fresnel), both against the project's Monte-Carlo reference of
// the same scene (tests/js/engine-scene.mjs: a sphere under an environment map, a point light and
// a rect area light), rendered by WebGLRenderer in headless Chromium for the Figure 2 material,
// beryllium and the textured inlay (through the coefficient table and its bake); and the coated car
// paint of examples/gltf as GLTFLoader builds it and as matc's GLTFLoader plugin does. The regions
// and what each must show are in tests/js/engine-reference.mjs.
//   node check-three-reference.mjs MATC MATERIALS_DIR EXAMPLES_WEB_DIR MATC_EXAMPLE_MAPS
//        EXAMPLES_TEXTURED_DIR [--markdown] [--images DIR] [--size N] [--lights PATH] [--timing]
import { modulePage, threeVersion } from "./browser-page.mjs";
import { runReferenceComparison } from "./engine-reference.mjs";

const kPage = (config) => modulePage(config, {
  head: `import * as THREE from "three";
import { RectAreaLightUniformsLib } from "three/addons/lights/RectAreaLightUniformsLib.js";
import { GLTFLoader } from "three/addons/loaders/GLTFLoader.js";
import { KTX2Loader } from "three/addons/loaders/KTX2Loader.js";
import { loadMatcBuild, useMatcFresnel } from "/web/three/matc-three.mjs";
import { matcGltfPlugin } from "/web/three/matc-gltf.mjs";
import { inlayMaps, referenceMaterial, threeScene } from "/checks/three-scene-page.mjs";
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
  const { camera, equirect, sphere, lights } = threeScene(THREE, scene);
  const environment = new THREE.PMREMGenerator(renderer).fromEquirectangular(equirect).texture;
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
    // Frame time (--timing, run in real time): the same frame drawn again, from an idle GPU
    // process to a pixel read back.
    if (withLights && config.timing?.kind && key.endsWith(config.timing.kind)) {
      const finish = () => renderer.readRenderTargetPixels(target, 0, 0, 1, 1, new Float32Array(4));
      finish();
      const start = performance.now();
      for (let i = 0; i < config.timing.frames; ++i) renderer.render(world, camera);
      finish();
      (out.frameTimes ??= []).push((performance.now() - start) / config.timing.frames);
    }
  };
  const reference = (material, maps) => referenceMaterial(THREE, scene, equirect, build.lut, material, maps);
  if (config.textured) {
    // The inlay: its maps, the bake's textures sampled trilinearly.
    const textured = config.textured;
    const maps = await inlayMaps(THREE);
    const ktx2 = new KTX2Loader().detectSupport(renderer);
    const baked = async (file) => ktx2.loadAsync("/textured/baked/" + file);
    if (!config.timing) draw(textured.name + " reference", reference(textured, maps), false);
    draw(textured.name + " stock", new THREE.MeshPhysicalMaterial({ metalness: 1, roughness: textured.roughness,
                                                                    map: maps.reflectivity }), true);
    draw(textured.name + " matc", useMatcFresnel(new THREE.MeshPhysicalMaterial({ roughness: textured.roughness }),
                                                 build, { reflectivityMap: maps.reflectivity, edgeTintMap: maps.edgeTint }), true);
    draw(textured.name + " baked", useMatcFresnel(new THREE.MeshPhysicalMaterial({ roughness: textured.roughness }),
        build, { baked: { c2Map: await baked("inlaid_metals_c2.ktx2"), c3Map: await baked("inlaid_metals_c3.ktx2"),
                          f0Map: await baked("inlaid_metals_f0.ktx2") } }), true);
  }
  for (const material of config.materials) {
    if (!config.timing) draw(material.name + " reference", reference(material), false);
    const stock = new THREE.MeshPhysicalMaterial({ metalness: 1, roughness: material.roughness,
      color: new THREE.Color().setRGB(...material.f0, THREE.LinearSRGBColorSpace) });
    draw(material.name + " stock", stock, true);
    const ours = useMatcFresnel(new THREE.MeshPhysicalMaterial({ roughness: material.roughness }), build,
                                { material: await build.loadMaterial(material.name) });
    draw(material.name + " matc", ours, true);
    const engineLtc = useMatcFresnel(new THREE.MeshPhysicalMaterial({ roughness: material.roughness }), build,
                                     { material: await build.loadMaterial(material.name) }, { areaLights: "engine" });
    draw(material.name + " matc-engine-ltc", engineLtc, true);
    const quality = useMatcFresnel(new THREE.MeshPhysicalMaterial({ roughness: material.roughness }), build,
                                   { material: await build.loadMaterial(material.name) }, { areaLights: "quality" });
    draw(material.name + " matc-quality", quality, true);
  }
  if (config.coated && !config.timing) {
    // The car paint as three.js loads the asset, and as matc's plugin does (its coated metal).
    const coated = config.coated;
    const loaded = async (loader) => {
      const gltf = await loader.loadAsync(coated.asset);
      const materials = [];
      gltf.scene.traverse((object) => { if (object.isMesh) materials.push(object.material); });
      return { material: materials[0], made: gltf.userData.matcMaterials ?? [] };
    };
    draw(coated.name + " reference", reference(coated), false);
    draw(coated.name + " stock", (await loaded(new GLTFLoader())).material, true);
    const ours = await loaded(new GLTFLoader().register(matcGltfPlugin({ build })));
    if (ours.made.length !== 1 || ours.material.userData.matc?.from !== "extension") {
      out.errors.push(coated.asset + ": matc's plugin did not make the car paint a matc metal from its extension");
    }
    draw(coated.name + " matc", ours.material, true);
  }
`,
});

await runReferenceComparison({ name: "three.js", prefix: "three", page: kPage, coated: true,
                               label: `three.js ${threeVersion()} (WebGLRenderer, ANGLE on SwiftShader)` },
                             process.argv.slice(2));
