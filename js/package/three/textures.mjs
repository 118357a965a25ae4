// Textures both three.js modules make (matc-three.mjs for WebGLRenderer, matc-three-webgpu.mjs for
// WebGPURenderer); THREE is the caller's namespace ("three" or "three/webgpu": one core).
import { f0TableTexels, kF0TableEntries } from "../matc-build.mjs";

// A clamped float texture of `data` without mips, filtered by `filter`, its texels read as they are.
function floatTexture(THREE, data, width, height, format, type, filter) {
  const texture = new THREE.DataTexture(data, width, height, format, type);
  texture.minFilter = texture.magFilter = filter;
  texture.wrapS = texture.wrapT = THREE.ClampToEdgeWrapping;
  texture.generateMipmaps = false;
  texture.colorSpace = THREE.NoColorSpace;
  texture.needsUpdate = true;
  return texture;
}

// A matc table (matc-build.mjs) as a linearly filtered, clamped float texture.
export function tableTexture(THREE, table) {
  return floatTexture(THREE, table.data, table.size, table.height, table.channels === 4 ? THREE.RGBAFormat : THREE.RGFormat,
                      table.half ? THREE.HalfFloatType : THREE.FloatType, THREE.LinearFilter);
}

// A filmed metal's table (build.loadMaterial's film.table) as a texture, made once per table: every
// material drawing the metal shares it.
const kFilmTextures = new WeakMap();
export function filmTexture(THREE, table) {
  if (!kFilmTextures.has(table)) kFilmTextures.set(table, tableTexture(THREE, table));
  return kFilmTextures.get(table);
}

// A textured metal's F0 table (a source's f0Table, as f0TableTexels lays it out) as the unfiltered
// RGBA32F texture MATC_COEFFICIENTS_FROM_F0_TABLE reads with texelFetch (the interpolation is the
// shader's).
export function f0TableTexture(THREE, table) {
  return floatTexture(THREE, f0TableTexels(table), kF0TableEntries, 6, THREE.RGBAFormat, THREE.FloatType,
                      THREE.NearestFilter);
}

// matc bake's mips average coefficients, so one trilinear sampler for all of them is exact;
// KTX2Loader leaves uncompressed textures at nearest filtering.
export function sampleTrilinearly(THREE, maps) {
  for (const map of maps.filter(Boolean)) {
    map.minFilter = map.mipmaps?.length > 1 ? THREE.LinearMipmapLinearFilter : THREE.LinearFilter;
    map.magFilter = THREE.LinearFilter;
    map.needsUpdate = true;
  }
}
