// A three.js GLTFLoader plugin that makes a glTF asset's metals matc metals as it loads
// (docs/gltf.md): each glTF material three.js built becomes a matc metal through useMatcFresnel
// (./matc-three.mjs). Its coefficients come from the material's MATC_materials_fresnel (written by
// `matc gltf`) when that fits the build's tables, with no compiler in the page; otherwise the
// package's WebAssembly compiler (`matc`, when given) compiles the glTF material's own JSON (the
// importer `matc import` runs: F0 from baseColorFactor, the F82 edge colour, the clear coat and
// its index), as it does for a coated metal, whose shader snippet only the compiler writes.
// Non-metals keep three.js's material. A metal matc cannot follow (an iridescent one), or one
// with neither the extension nor a compiler, keeps three.js's material too, with a console
// warning that says why.
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
// Without the compiler: loadMatcBuild("build/") of `matc -o build --shared-only`, and
// matcGltfPlugin({ build }) for assets written by `matc gltf`.
import { MatcWebError, gltfExtensionMaterial, kGltfFresnelExtension } from "../matc-build.mjs";
import { useMatcFresnel } from "./matc-three.mjs";

// The asset's material `index` alone, as a glTF asset the importer reads (a material needs no
// other part of the asset to be compiled).
function materialAsset(json, index) {
  return JSON.stringify({ asset: { version: "2.0" }, materials: [json.materials[index]],
                          extensionsUsed: json.extensionsUsed ?? [] });
}

const isMetal = (material) => (material.pbrMetallicRoughness?.metallicFactor ?? 1) > 0;

// Returns the plugin for `new GLTFLoader().register(...)`. build: loadMatcBuild(...) of
// matc/three; matc: createMatc()'s instance, to compile metals that carry no usable
// MATC_materials_fresnel (optional); options.compile: the compile's options (basis, colorSpace:
// glTF's colours are linear Rec.709); options.areaLights: as useMatcFresnel takes it.
export function matcGltfPlugin({ matc = null, build, compile = {}, areaLights = "matc" }) {
  if ((matc !== null && typeof matc?.parseMaterials !== "function") || typeof build?.loadMaterial !== "function") {
    throw new MatcWebError("matcGltfPlugin takes { build: await loadMatcBuild(...), matc?: await createMatc() }");
  }
  return (parser) => ({
    name: "matc",
    async afterRoot(gltf) {
      const where = (index) => `glTF materials[${index}] "${parser.json.materials[index].name ?? ""}"`;
      const warn = (index, message) => console.warn(`matc: ${where(index)} keeps three.js's Fresnel: ${message}`);
      // glTF material index -> { metal: build.loadMaterial's, from: "extension" | "compiled" }, or null.
      const compiled = new Map();
      const compileInPage = async (index) => {
        try {
          const [material] = matc.parseMaterials(materialAsset(parser.json, index), "asset.gltf");
          return material ? { metal: await build.loadMaterial(matc.compile(material, compile)), from: "compiled" } : null;
        } catch (error) {
          // Not a metal: three.js's material stays, silently. Anything else (a value matc
          // refuses, options that do not fit the build) is said.
          if (!/holds no metal/.test(error.message)) warn(index, error.message);
          return null;
        }
      };
      const metalOf = async (index) => {
        if (compiled.has(index)) return compiled.get(index);
        const json = parser.json.materials[index];
        const extension = json.extensions?.[kGltfFresnelExtension];
        let found = null;
        let refusal = null;
        if (extension && isMetal(json)) {
          try {
            found = { metal: gltfExtensionMaterial(build, extension), from: "extension" };
          } catch (error) {
            refusal = error.message;
          }
        }
        if (!found && matc) {
          found = await compileInPage(index);
        } else if (!found && isMetal(json)) {
          warn(index, refusal ?? `no ${kGltfFresnelExtension} (matc gltf writes it) and no compiler in the page (matc)`);
        }
        compiled.set(index, found);
        return found;
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
        const found = await metalOf(index);
        if (!found) continue;
        try {
          useMatcFresnel(material, build, { material: found.metal }, { areaLights });
          Object.assign(material.userData.matc, { gltfMaterial: index, from: found.from });
          made.push(material);
        } catch (error) {
          warn(index, error.message);
        }
      }
      gltf.userData.matcMaterials = made;
    },
  });
}
