// The three.js GLTFLoader plugin of matc/three/gltf (./matc-gltf.mjs) for WebGPURenderer
// (docs/gltf.md): each glTF metal three.js built (a MeshStandardMaterial or MeshPhysicalMaterial)
// becomes a matc metal of ./matc-three-webgpu.mjs: its node material, made as WebGPURenderer makes
// one from it (every property copied), with matc's lighting model. The metals come as they do for
// WebGLRenderer: from the material's MATC_materials_fresnel (a coated metal's WGSL snippet from
// the build directory that compiled the asset, or from matc's WGSL template filled with the
// extension's values), else compiled in the page; non-metals keep three.js's material, and a metal
// matc cannot follow keeps it with a console warning that says why.
//
//   import * as THREE from "three/webgpu";
//   import { createMatc } from "matc";
//   import { compiledMatcBuildFiles } from "matc/build";
//   import { loadMatcBuild } from "matc/three/webgpu";
//   import { matcGltfPlugin } from "matc/three/webgpu/gltf";
//   const matc = await createMatc();
//   const build = await loadMatcBuild(await compiledMatcBuildFiles(matc, { language: "wgsl" }));
//   const gltf = await new GLTFLoader().register(matcGltfPlugin({ matc, build })).loadAsync("car.glb");
import * as THREE from "three/webgpu";
import { MatcWebError } from "../matc-build.mjs";
import { threeGltfPlugin } from "./gltf-plugin.mjs";
import { useMatcFresnel } from "./matc-three-webgpu.mjs";

// The node material WebGPURenderer would draw `material` with (its NodeLibrary.fromMaterial: a
// node material of the same kind holding every property), with its own identity and userData.
function nodeMaterialOf(material) {
  const node = material.isMeshPhysicalMaterial ? new THREE.MeshPhysicalNodeMaterial() : new THREE.MeshStandardNodeMaterial();
  for (const key in material) {
    if (key !== "type" && key !== "uuid" && key !== "id" && key !== "userData") node[key] = material[key];
  }
  node.userData = { ...material.userData };
  return node;
}

// Returns the plugin for `new GLTFLoader().register(...)`. build: loadMatcBuild(...) of
// matc/three/webgpu (a WGSL build); matc, options.compile, options.areaLights: as matc/three/gltf
// takes them.
export function matcGltfPlugin({ matc = null, build, compile = {}, areaLights = "matc" }) {
  const plugin = threeGltfPlugin({
    matc, build, compile, what: "matcGltfPlugin (WebGPU)",
    make: (material, source, options) => {
      if (!material.isMeshStandardMaterial) throw new MatcWebError("three.js built no MeshStandardMaterial for it");
      // A coated metal made from the extension carries its snippet; this build makes its functions.
      if (source.material?.coat && !source.material.coat.functions) build.withCoatFunctions(source.material);
      return useMatcFresnel(nodeMaterialOf(material), build, source, { areaLights, ...options });
    },
  });
  // A build of matc/three (WebGL: GLSL) passes the shared check; its metals could not draw here.
  if (typeof build.withCoatFunctions !== "function") {
    throw new MatcWebError("matcGltfPlugin (WebGPU) takes matc/three/webgpu's loadMatcBuild(...), a WGSL build");
  }
  return plugin;
}
