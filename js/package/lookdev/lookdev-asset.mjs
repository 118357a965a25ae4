// An opened glTF asset for the look-development page's asset view: loaded twice by three.js's
// GLTFLoader, once with matc's plugin (matc/three/gltf: its metals become matc metals, glTF's
// metal-rough model per pixel where the metalness is partial or textured, compiled in the page)
// and once as three.js loads it, so that the view shows the two side by side. The files a .gltf
// names (buffers, images) come from those dropped with it, by name; anything else it names is not
// fetched: the load fails with a message that names the file (the page is offline by design).
import * as THREE from "three";
import { GLTFLoader } from "three/addons/loaders/GLTFLoader.js";
import { matcGltfPlugin } from "../three/matc-gltf.mjs";

// The asset's glTF materials as matc's loader made them: { name (as written), index, metalRough
// (mixed per pixel with three.js's dielectric), coated, from ("extension" or "compiled") }.
function madeMetals(gltf) {
  return (gltf.userData.matcMaterials ?? []).map((material) => ({
    name: material.name, index: material.userData.matc.gltfMaterial,
    metalRough: "MATC_METAL_ROUGH" in (material.defines ?? {}), coated: "MATC_COATED" in (material.defines ?? {}),
    from: material.userData.matc.from,
  }));
}

// Text from the asset (its file name, three.js's message, which may quote it) as the page shows it:
// control characters and quotes escaped as JSON escapes them, never raw.
export const escapedText = (text) => JSON.stringify(String(text)).slice(1, -1);

// The number of meshes under `root` (an asset of materials only has none: nothing to show).
function meshCount(root) {
  let count = 0;
  root.traverse((object) => { if (object.isMesh) count += 1; });
  return count;
}

// Loads `bytes` (a .glb's, or a .gltf's text as bytes) named `path`, with `files` (name -> bytes)
// for the URIs it names. `matc`: createMatc()'s instance; `build`: loadMatcBuild's (matc/three).
// Resolves to { matc, engine (the two scenes), metals (madeMetals), meshes } or rejects with an
// Error whose message says why (three.js's, or a file the asset names that was not dropped).
export async function loadAssetPair({ bytes, path, files = {}, matc, build }) {
  const urls = new Map();
  const manager = new THREE.LoadingManager();
  const missing = [];
  manager.setURLModifier((url) => {
    if (url.startsWith("data:") || url.startsWith("blob:")) return url;
    const name = decodeURIComponent(url.split("/").pop());
    if (!Object.hasOwn(files, name)) {
      missing.push(name);
      return "data:application/octet-stream;base64,";  // fails as empty, not as a network request
    }
    if (!urls.has(name)) urls.set(name, URL.createObjectURL(new Blob([files[name]])));
    return urls.get(name);
  });
  const data = bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength);
  try {
    const load = async (loader) => {
      try {
        return await loader.parseAsync(data, "");
      } catch (error) {
        const named = missing.length > 0 ? `: it names ${JSON.stringify(missing[0])}, which was not dropped with it` : "";
        throw new Error(`${escapedText(path)}: three.js could not load the asset${named || `: ${escapedText(error.message)}`}`);
      }
    };
    const engine = await load(new GLTFLoader(manager));
    const withMatc = await load(new GLTFLoader(manager).register(matcGltfPlugin({ matc, build })));
    // An asset without a scene (materials only) shows nothing.
    const engineScene = engine.scene ?? new THREE.Group();
    return { matc: withMatc.scene ?? new THREE.Group(), engine: engineScene, metals: madeMetals(withMatc),
             meshes: meshCount(engineScene) };
  } finally {
    for (const url of urls.values()) URL.revokeObjectURL(url);
  }
}

// Frees what the two scenes hold on the GPU (geometries, materials, textures).
export function disposeAsset(asset) {
  for (const root of [asset.matc, asset.engine]) {
    root.traverse((object) => {
      if (!object.isMesh) return;
      object.geometry.dispose();
      for (const material of Array.isArray(object.material) ? object.material : [object.material]) {
        for (const value of Object.values(material)) if (value?.isTexture) value.dispose();
        material.dispose();
      }
    });
  }
}
