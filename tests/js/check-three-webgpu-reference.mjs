// three.js's WebGPURenderer with matc's Fresnel (js/package/three/matc-three-webgpu.mjs) and its
// stock MeshPhysicalNodeMaterial (F0 = the material's F0, Schlick's Fresnel), both against the
// project's Monte-Carlo reference of the scene of tests/js/engine-scene.mjs, in headless Chromium
// (WebGPU: Dawn on SwiftShader), for the Figure 2 material, beryllium and the textured inlay
// (through the coefficient table and its bake); the regions and what each must show are in
// tests/js/engine-reference.mjs. WebGPURenderer has no GLSL ShaderMaterial: the reference is drawn
// by a WebGLRenderer on the same page, with the same camera and geometry (three's one core).
// WebGPU's adapter does not settle under virtual time: the page runs in real time and posts its
// result.
//   node check-three-webgpu-reference.mjs MATC MATERIALS_DIR EXAMPLES_WEB_DIR MATC_EXAMPLE_MAPS
//        EXAMPLES_TEXTURED_DIR [--markdown] [--images DIR] [--size N] [--lights PATH] [--timing]
import { modulePage, threeVersion } from "./browser-page.mjs";
import { runReferenceComparison } from "./engine-reference.mjs";

const kPage = (config) => modulePage(config, {
  head: `import * as THREE from "three/webgpu";
import * as THREE_GL from "three";
import { RectAreaLightTexturesLib } from "three/addons/lights/RectAreaLightTexturesLib.js";
import { KTX2Loader } from "three/addons/loaders/KTX2Loader.js";
import { loadMatcBuild, useMatcFresnel } from "/web/three/matc-three-webgpu.mjs";
import { loadMatcBuild as loadMatcBuildForWebGL } from "/web/three/matc-three.mjs";
import { inlayMaps, referenceMaterial, threeScene, webGpuRenderer } from "/checks/three-scene-page.mjs";
`,
  body: `
  const scene = config.scene;
  const size = scene.size;
  out.images = {};
  const renderer = await webGpuRenderer(THREE, RectAreaLightTexturesLib);
  renderer.setClearColor(0x000000, 0);
  const build = await loadMatcBuild("/out/");
  const target = new THREE.RenderTarget(size, size, { type: THREE.FloatType });
  const { camera, equirect, sphere, lights } = threeScene(THREE, scene);
  // Rows as WebGLRenderer reads them (bottom-up): WebGPU reads a target top-down.
  const bottomUp = (pixels) => {
    const rows = new Float32Array(size * size * 4);
    for (let y = 0; y < size; ++y) rows.set(pixels.subarray(4 * size * y, 4 * size * (y + 1)), 4 * size * (size - 1 - y));
    return rows;
  };
  const draw = async (key, material) => {
    const world = new THREE.Scene();
    world.add(new THREE.Mesh(sphere, material));
    world.environment = equirect;
    world.add(...lights());
    renderer.setRenderTarget(target);
    await renderer.renderAsync(world, camera);  // compiles
    const pixels = await renderer.readRenderTargetPixelsAsync(target, 0, 0, size, size);
    out.images[key] = base64Floats(bottomUp(pixels));
    // Frame time (--timing): the same frame drawn again, from an idle GPU process to a pixel
    // read back.
    if (config.timing?.kind && key.endsWith(config.timing.kind)) {
      await renderer.readRenderTargetPixelsAsync(target, 0, 0, 1, 1);
      const start = performance.now();
      for (let i = 0; i < config.timing.frames; ++i) renderer.render(world, camera);
      await renderer.readRenderTargetPixelsAsync(target, 0, 0, 1, 1);
      (out.frameTimes ??= []).push((performance.now() - start) / config.timing.frames);
    }
  };
  // The references, on WebGL2 (skipped when timing).
  const drawReferences = async (materials, maps) => {
    if (config.timing) return;
    const gl = new THREE_GL.WebGLRenderer({ canvas: document.createElement("canvas") });
    gl.debug.onShaderError = (context, program, vertex, fragment) =>
      out.errors.push(context.getShaderInfoLog(fragment) || context.getShaderInfoLog(vertex) || context.getProgramInfoLog(program));
    gl.setClearColor(0x000000, 0);
    const lut = (await loadMatcBuildForWebGL("/out/")).lut;
    const glTarget = new THREE_GL.WebGLRenderTarget(size, size, { type: THREE_GL.FloatType });
    const environment = threeScene(THREE_GL, scene).equirect;
    for (const material of materials) {
      const world = new THREE_GL.Scene();
      world.add(new THREE_GL.Mesh(sphere, referenceMaterial(THREE_GL, scene, environment, lut, material,
                                                            material === config.textured ? maps : null)));
      gl.setRenderTarget(glTarget);
      gl.render(world, camera);
      const pixels = new Float32Array(size * size * 4);
      gl.readRenderTargetPixels(glTarget, 0, 0, size, size, pixels);
      out.images[material.name + " reference"] = base64Floats(pixels);
    }
    gl.dispose();
  };
  const textured = config.textured;
  const maps = await inlayMaps(THREE);
  await drawReferences([textured, ...config.materials], await inlayMaps(THREE_GL));
  const ktx2 = new KTX2Loader().detectSupport(renderer);
  const baked = async (file) => ktx2.loadAsync("/textured/baked/" + file);
  const physical = (parameters) => new THREE.MeshPhysicalNodeMaterial(parameters);
  await draw(textured.name + " stock", physical({ metalness: 1, roughness: textured.roughness, map: maps.reflectivity }));
  await draw(textured.name + " matc", useMatcFresnel(physical({ roughness: textured.roughness }), build,
                                                     { reflectivityMap: maps.reflectivity, edgeTintMap: maps.edgeTint }));
  await draw(textured.name + " baked", useMatcFresnel(physical({ roughness: textured.roughness }), build,
      { baked: { c2Map: await baked("inlaid_metals_c2.ktx2"), c3Map: await baked("inlaid_metals_c3.ktx2"),
                 f0Map: await baked("inlaid_metals_f0.ktx2") } }));
  for (const material of config.materials) {
    await draw(material.name + " stock", physical({ metalness: 1, roughness: material.roughness,
        color: new THREE.Color().setRGB(...material.f0, THREE.LinearSRGBColorSpace) }));
    await draw(material.name + " matc", useMatcFresnel(physical({ roughness: material.roughness }), build,
                                                       { material: await build.loadMaterial(material.name) }));
    await draw(material.name + " matc-engine-ltc", useMatcFresnel(physical({ roughness: material.roughness }), build,
        { material: await build.loadMaterial(material.name) }, { areaLights: "engine" }));
    await draw(material.name + " matc-quality", useMatcFresnel(physical({ roughness: material.roughness }), build,
        { material: await build.loadMaterial(material.name) }, { areaLights: "quality" }));
  }
`,
});

await runReferenceComparison({
  name: "three.js", prefix: "three_webgpu",
  label: `three.js ${threeVersion()} (WebGPURenderer, Dawn on SwiftShader; the reference on WebGLRenderer)`,
  page: kPage,
  runPage: { realTime: true, browserArgs: ["--enable-unsafe-webgpu", "--use-webgpu-adapter=swiftshader"] },
}, process.argv.slice(2));
