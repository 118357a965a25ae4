// In-page side of three.js's glTF loader checks (check-three-gltf.mjs for WebGLRenderer,
// check-three-webgpu-gltf.mjs for WebGPURenderer): the console's errors and warnings recorded,
// and the car asset loaded by GLTFLoader with the renderer's matc plugin three ways (compiled in
// the page; as `matc gltf` wrote it, no compiler; the same with the build directory), each
// material's kind noted as gltf-loader-checks.mjs checks it.
import { GLTFLoader } from "three/addons/loaders/GLTFLoader.js";

export function recordConsole(out) {
  out.console = [];
  for (const level of ["error", "warn"]) {
    const original = console[level].bind(console);
    console[level] = (...args) => { out.console.push(level + ": " + args.join(" ")); original(...args); };
  }
}

// What a loaded material became: "engine" (three.js's own), or its matc source and origin.
function kindOf(material) {
  const matc = material.userData.matc;
  if (!matc) return "engine";
  const { source } = matc;
  const kind = source.schlick ? "per-pixel" : (source.f0Table ? "f0-table " : "") + (source.material.coat ? "coated" : source.material.film ? "filmed" : "bare");
  const template = /from MATC_materials_fresnel/.test(source.material?.coat?.snippet) ? " (template)" : "";
  return `${kind} ${matc.from}${template}`;
}

// Returns { <load>: { byName: the meshes' materials by name, kinds, made } } and sets out.kinds and
// out.made. matcGltfPlugin: the renderer's; build: its loadMatcBuild of the compiled files;
// directoryBuild: of /build/.
export async function loadCarThreeWays(out, { matcGltfPlugin, matc, build, directoryBuild }) {
  const loads = {};
  for (const [name, url, options] of [["compiled", "/assets/car.glb", { matc, build }],
                                      ["extension", "/assets/car_matc.glb", { build }],
                                      ["directory", "/assets/car_matc.glb", { build: directoryBuild }]]) {
    out.console.push("-- " + name);
    const gltf = await new GLTFLoader().register(matcGltfPlugin(options)).loadAsync(url);
    const byName = {};
    gltf.scene.traverse((object) => { if (object.isMesh) byName[object.material.name] = object.material; });
    loads[name] = { byName, made: gltf.userData.matcMaterials,
                    kinds: Object.fromEntries(Object.entries(byName).map(([key, material]) => [key, kindOf(material)])) };
  }
  out.kinds = Object.fromEntries(Object.entries(loads).map(([name, load]) => [name, load.kinds]));
  out.made = Object.fromEntries(Object.entries(loads).map(([name, load]) => [name, load.made.length]));
  return loads;
}
