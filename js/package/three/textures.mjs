// Textures both three.js modules make (matc-three.mjs for WebGLRenderer, matc-three-webgpu.mjs for
// WebGPURenderer); THREE is the caller's namespace ("three" or "three/webgpu": one core).

// A matc table (matc-build.mjs) as a linearly filtered, clamped float texture.
export function tableTexture(THREE, table) {
  const texture = new THREE.DataTexture(table.data, table.size, table.size,
                                        table.channels === 4 ? THREE.RGBAFormat : THREE.RGFormat,
                                        table.half ? THREE.HalfFloatType : THREE.FloatType);
  texture.minFilter = texture.magFilter = THREE.LinearFilter;
  texture.wrapS = texture.wrapT = THREE.ClampToEdgeWrapping;
  texture.generateMipmaps = false;
  texture.colorSpace = THREE.NoColorSpace;
  texture.needsUpdate = true;
  return texture;
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
