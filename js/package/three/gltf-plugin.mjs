// What three.js's two GLTFLoader plugins share (matc-gltf.mjs for WebGLRenderer,
// matc-gltf-webgpu.mjs for WebGPURenderer): after the asset loads, each glTF metal's material
// three.js built becomes a matc metal through `make` (the renderer's useMatcFresnel), which may
// return another material (WebGPURenderer's node material): every mesh that used the old one then
// uses it, and the parser's associations follow. Non-metals, and metals matc cannot follow, keep
// three.js's material (the latter with a console warning that says why). Imports no three.js, so
// that a page loads the one its renderer needs.
import { checkGltfLoaderOptions, gltfMetals } from "../matc-build.mjs";

// make(material, source, { metalRough, bareFilm }) -> the matc material (useMatcFresnel's result,
// with those options: gltfMetals decides them). `what` names the plugin in the
// options' error.
export function threeGltfPlugin({ matc, build, compile, what, make }) {
  checkGltfLoaderOptions(matc, build, what);
  return (parser) => ({
    name: "matc",
    async afterRoot(gltf) {
      // The asset's name escaped (JSON), so that it cannot forge console lines.
      const where = (index) => `glTF materials[${index}] ${JSON.stringify(String(parser.json.materials[index].name ?? ""))}`;
      const warn = (index, message) => console.warn(`matc: ${where(index)} keeps three.js's Fresnel: ${message}`);
      const note = (index, message) => console.warn(`matc: ${where(index)}: ${message}`);
      const metals = gltfMetals({ matc, build, compile, json: parser.json, warn, note });
      // Each material with the places that use it (a mesh holds one, or an array of them).
      const uses = new Map();
      gltf.scene.traverse((object) => {
        if (!object.isMesh) return;
        const list = Array.isArray(object.material) ? object.material : [object.material];
        list.forEach((material, slot) => {
          if (!uses.has(material)) uses.set(material, []);
          uses.get(material).push({ object, slot });
        });
      });
      const made = [];
      for (const [material, places] of uses) {
        const index = parser.associations.get(material)?.materials;
        if (index === undefined) continue;
        const found = await metals.metalOf(index);
        if (!found) continue;
        try {
          const matcMaterial = make(material, found.source, { metalRough: found.metalRough, bareFilm: found.bareFilm });
          Object.assign(matcMaterial.userData.matc, { gltfMaterial: index, from: found.from });
          if (matcMaterial !== material) {
            for (const { object, slot } of places) {
              if (Array.isArray(object.material)) object.material[slot] = matcMaterial;
              else object.material = matcMaterial;
            }
            parser.associations.set(matcMaterial, parser.associations.get(material));
          }
          made.push(matcMaterial);
        } catch (error) {
          warn(index, error.message);
        }
      }
      gltf.userData.matcMaterials = made;
    },
  });
}
