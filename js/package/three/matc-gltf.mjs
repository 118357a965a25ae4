// A three.js GLTFLoader plugin that makes a glTF asset's metals matc metals as it loads
// (docs/gltf.md): each glTF material three.js built becomes a matc metal through useMatcFresnel
// (./matc-three.mjs), compiled in the page by the package's WebAssembly compiler from that glTF
// material's own JSON (the importer `matc import` runs: F0 from baseColorFactor, the F82 edge
// colour, the clear coat and its index). Non-metals keep three.js's material. A metal matc cannot
// follow (an iridescent one) keeps three.js's material too, with a console warning that says why.
//
//   import { createMatc } from "matc";
//   import { compiledMatcBuildFiles } from "matc/build";
//   import { loadMatcBuild } from "matc/three";
//   import { matcGltfPlugin } from "matc/three/gltf";
//   const matc = await createMatc();
//   const build = await loadMatcBuild(await compiledMatcBuildFiles(matc));
//   const loader = new GLTFLoader().register(matcGltfPlugin({ matc, build }));
//   const gltf = await loader.loadAsync("car.glb");   // its metals now use matc's Fresnel
import { MatcWebError } from "../matc-build.mjs";
import { useMatcFresnel } from "./matc-three.mjs";

// The asset's material `index` alone, as a glTF asset the importer reads (a material needs no
// other part of the asset to be compiled).
function materialAsset(json, index) {
  return JSON.stringify({ asset: { version: "2.0" }, materials: [json.materials[index]],
                          extensionsUsed: json.extensionsUsed ?? [] });
}

// Returns the plugin for `new GLTFLoader().register(...)`. matc: createMatc()'s instance; build:
// loadMatcBuild(await compiledMatcBuildFiles(matc)) of matc/three; options.compile: the compile's
// options (basis, colorSpace: glTF's colours are linear Rec.709); options.areaLights: as
// useMatcFresnel takes it.
export function matcGltfPlugin({ matc, build, compile = {}, areaLights = "matc" }) {
  if (typeof matc?.parseMaterials !== "function" || typeof build?.loadMaterial !== "function") {
    throw new MatcWebError("matcGltfPlugin takes { matc: await createMatc(), build: await loadMatcBuild(...) }");
  }
  return (parser) => ({
    name: "matc",
    async afterRoot(gltf) {
      const compiled = new Map();  // glTF material index -> build.loadMaterial's, or null
      const metalOf = async (index) => {
        if (!compiled.has(index)) {
          let loaded = null;
          try {
            const [material] = matc.parseMaterials(materialAsset(parser.json, index), "asset.gltf");
            loaded = material ? await build.loadMaterial(matc.compile(material, compile)) : null;
          } catch (error) {
            // Not a metal: three.js's material stays, silently. Anything else (a value matc
            // refuses, options that do not fit the build) is said.
            if (!/holds no metal/.test(error.message)) {
              console.warn(`matc: glTF materials[${index}] "${parser.json.materials[index].name ?? ""}" keeps ` +
                           `three.js's Fresnel: ${error.message}`);
            }
          }
          compiled.set(index, loaded);
        }
        return compiled.get(index);
      };
      const materials = new Set();
      gltf.scene.traverse((object) => {
        if (!object.isMesh) return;
        for (const material of Array.isArray(object.material) ? object.material : [object.material]) {
          materials.add(material);
        }
      });
      const made = [];
      for (const material of materials) {
        const index = parser.associations.get(material)?.materials;
        if (index === undefined) continue;
        const metal = await metalOf(index);
        if (!metal) continue;
        try {
          useMatcFresnel(material, build, { material: metal }, { areaLights });
          material.userData.matc.gltfMaterial = index;
          made.push(material);
        } catch (error) {
          console.warn(`matc: glTF materials[${index}] "${parser.json.materials[index].name ?? ""}" keeps ` +
                       `three.js's Fresnel: ${error.message}`);
        }
      }
      gltf.userData.matcMaterials = made;
    },
  });
}
