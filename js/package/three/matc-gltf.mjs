// A three.js GLTFLoader plugin that makes a glTF asset's metals matc metals as it loads
// (docs/gltf.md): each glTF material three.js built becomes a matc metal through useMatcFresnel
// (./matc-three.mjs). Its coefficients come from the material's MATC_materials_fresnel (written by
// `matc gltf`) when that fits the build's tables, with no compiler in the page; otherwise the
// package's WebAssembly compiler (`matc`, when given) compiles the glTF material's own JSON (the
// importer `matc import` runs: F0 from baseColorFactor, the F82 edge colour, the clear coat and
// its index). A coated metal's two-lobe shader snippet comes from the compiler in the page, from a
// build directory that compiled the same asset, or from matc's template filled with the
// extension's values (gltfMetals in ../matc-build.mjs, shared with the Babylon.js loader extension). Non-metals keep
// three.js's material. A metal matc cannot follow (an iridescent one), or one with neither the
// extension nor a compiler, keeps three.js's material too, with a console warning that says why.
//
//   import { createMatc } from "matc";
//   import { compiledMatcBuildFiles } from "matc/build";
//   import { loadMatcBuild } from "matc/three";
//   import { matcGltfPlugin } from "matc/three/gltf";
//   const matc = await createMatc();
//   const build = await loadMatcBuild(await compiledMatcBuildFiles(matc));
//   const loader = new GLTFLoader().register(matcGltfPlugin({ matc, build }));
//   const gltf = await loader.loadAsync("car.glb");   // its metals now use matc's Fresnel
//
// Without the compiler: loadMatcBuild("build/") of a build directory (`matc -o build --shared-only`:
// the tables), and matcGltfPlugin({ build }) for the asset `matc gltf` wrote. WebGPURenderer:
// matc/three/webgpu/gltf (./matc-gltf-webgpu.mjs).
import { threeGltfPlugin } from "./gltf-plugin.mjs";
import { useMatcFresnel } from "./matc-three.mjs";

// Returns the plugin for `new GLTFLoader().register(...)`. build: loadMatcBuild(...) of
// matc/three; matc: createMatc()'s instance, to compile metals that carry no usable
// MATC_materials_fresnel (optional); options.compile: the compile's options (basis, colorSpace:
// glTF's colours are linear Rec.709); options.areaLights: as useMatcFresnel takes it.
export function matcGltfPlugin({ matc = null, build, compile = {}, areaLights = "matc" }) {
  return threeGltfPlugin({ matc, build, compile, what: "matcGltfPlugin",
                           make: (material, source, options) =>
                             useMatcFresnel(material, build, source, { areaLights, ...options }) });
}
