// A Babylon.js glTF loader extension that makes a glTF asset's metals matc metals as it loads
// (docs/gltf.md): each glTF material Babylon's loader builds (a PBRMaterial) becomes a matc metal
// through useMatcFresnel (./matc-babylon.mjs) once its properties are loaded, with the
// coefficients from the material's MATC_materials_fresnel (written by `matc gltf`) when that fits
// the build's tables, or compiled in the page by the package's WebAssembly compiler (`matc`, when
// given); a coated metal's snippet comes from the compiler, from a build directory that compiled
// the same asset, or from matc's template filled with the extension's values (gltfMetals in
// ../matc-build.mjs, shared with three.js's plugin).
// Non-metals keep Babylon's material; a metal matc cannot follow (an iridescent one), or one with
// neither the extension nor a compiler, keeps it too, with a console warning that says why.
//
//   import "@babylonjs/loaders/glTF/2.0/index.js";
//   import { LoadAssetContainerAsync } from "@babylonjs/core/Loading/sceneLoader.js";
//   import { loadMatcBuild } from "matc/babylon";
//   import { registerMatcGltfExtension } from "matc/babylon/gltf";
//   const build = await loadMatcBuild("build/", scene);        // matc -o build car.glb
//   const matcGltf = registerMatcGltfExtension({ build });     // + matc: await createMatc()
//   const container = await LoadAssetContainerAsync("car_matc.glb", scene);
//   matcGltf.materials;                                        // the PBRMaterials made matc metals
//   matcGltf.unregister();
import { registerGLTFExtension, unregisterGLTFExtension }
  from "@babylonjs/loaders/glTF/2.0/glTFLoaderExtensionRegistry.js";
import { checkGltfLoaderOptions, gltfMetals } from "../matc-build.mjs";
import { useMatcFresnel } from "./matc-babylon.mjs";

// The loader extension's name in Babylon's registry (not a glTF extension: it runs on every asset).
export const kMatcGltfLoaderExtension = "matc";

class MatcGltfLoaderExtension {
  constructor(loader, { matc, build, compile, areaLights, made }) {
    this.name = kMatcGltfLoaderExtension;
    this.enabled = true;
    // Before every glTF extension Babylon registers (theirs are 100 and above), so that the
    // material's own extensions (clear coat, specular, ...) have run when it is made a matc metal.
    this.order = 1;
    this.loader = loader;
    this.made = made;
    this.areaLights = areaLights;
    this.build = build;
    // The asset's name escaped (JSON), so that it cannot forge console lines.
    const where = (index) => `glTF materials[${index}] ${JSON.stringify(String(loader.gltf.materials[index].name ?? ""))}`;
    this.warn = (index, message) => console.warn(`matc: ${where(index)} keeps Babylon.js's Fresnel: ${message}`);
    const note = (index, message) => console.warn(`matc: ${where(index)}: ${message}`);
    this.note = note;
    this.metals = gltfMetals({ matc, build, compile, json: loader.gltf, warn: this.warn, note });
  }

  dispose() {
    this.loader = null;
  }

  // The material's properties as Babylon loads them (its other extensions included), then matc's
  // Fresnel over them.
  loadMaterialPropertiesAsync(context, material, babylonMaterial) {
    return this.loader.loadMaterialPropertiesAsync(context, material, babylonMaterial).then(async () => {
      const found = await this.metals.metalOf(material.index);
      if (!found) return;
      // glTF's metal-rough mix per pixel (under a matc coat and Babylon's OpenPBR conductor model too).
      try {
        useMatcFresnel(babylonMaterial, this.build, found.source,
                       { areaLights: this.areaLights, metalRough: found.metalRough, bareFilm: found.bareFilm });
        babylonMaterial.metadata = { ...babylonMaterial.metadata, matc: { gltfMaterial: material.index, from: found.from } };
        this.made.push(babylonMaterial);
      } catch (error) {
        this.warn(material.index, error.message);
      }
    });
  }
}

// Registers the loader extension for the glTF assets Babylon loads from now on (every one, until
// unregister()). build: loadMatcBuild(..., scene) of matc/babylon; matc: createMatc()'s instance,
// to compile metals with no usable MATC_materials_fresnel (optional); compile: the compile's
// options; areaLights: as useMatcFresnel takes it. Returns { materials: the PBRMaterials made
// matc metals so far, unregister() }.
export function registerMatcGltfExtension({ matc = null, build, compile = {}, areaLights = "matc" }) {
  checkGltfLoaderOptions(matc, build, "registerMatcGltfExtension");
  const made = [];
  unregisterGLTFExtension(kMatcGltfLoaderExtension);
  registerGLTFExtension(kMatcGltfLoaderExtension, false,
                        (loader) => new MatcGltfLoaderExtension(loader, { matc, build, compile, areaLights, made }));
  return { materials: made, unregister: () => unregisterGLTFExtension(kMatcGltfLoaderExtension) };
}
