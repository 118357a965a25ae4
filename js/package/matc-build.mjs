// What the web engine integrations share (three/matc-three.mjs, babylon/matc-babylon.mjs), the
// package's "matc/build": one module per concern in integration/, re-exported here.
//   - errors.mjs: the version of matc's outputs read, MatcWebError;
//   - shader-patches.mjs: patching an engine's shader text at anchors found exactly once;
//   - physical-glsl.mjs: the GLSL both WebGL integrations put into their engine's shader;
//   - build-directory.mjs: a matc build directory, or the same compiled in the page;
//   - gltf-extension.mjs: MATC_materials_fresnel and the glTF loaders' choice of metals;
//   - f0-table.mjs, coefficient-rows.mjs: F0 tables and coefficient rows, checked;
//   - sources.mjs: useMatcFresnel's options and coefficient sources, checked;
//   - basis-layers.mjs: a per-material build's bases (matc --basis auto) and each one's functions.
export { compiledMatcBuildFiles, kFilmTableHeight, kFilmTableWidth, loadMatcBuildFiles, matcBuildFiles }
  from "./integration/build-directory.mjs";
export { MatcWebError, kMatcVersion } from "./integration/errors.mjs";
export { f0TableTexels, kF0TableEntries } from "./integration/f0-table.mjs";
export { checkGltfLoaderOptions, gltfExtensionMaterial, gltfMetals, isGltfMetalRough, kGltfFresnelExtension }
  from "./integration/gltf-extension.mjs";
export { declarationsGlsl, lobesGlsl, pixelSetupGlsl } from "./integration/physical-glsl.mjs";
export { anchorPattern, checkAnchors, countAnchor } from "./integration/shader-patches.mjs";
export { checkAreaLights, checkIridescence, checkLayeredAreaLights, rgbOf, sourceBasis, sourceKind } from "./integration/sources.mjs";
export { basisAliasesGlsl, basisDefine, basisSuffix, buildBases, holdsBasis } from "./integration/basis-layers.mjs";
