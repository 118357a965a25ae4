// A three.js material whose specular Fresnel is matc's: the GLSL files matc writes, unchanged, in a
// ShaderMaterial (GLSL ES 3.00 on WebGL2), with the preintegrated table and energy compensation.
// Tested in headless Chromium by tests/js/check-three.mjs; docs/shaders.md shows this file.
//
//   import * as THREE from "three";
//   const material = createMatcMaterial(THREE, {
//     library: await (await fetch("matc_fresnel.glsl")).text(),
//     material: await (await fetch("gold.glsl")).text(), name: "gold",
//     lut: new Float32Array(await (await fetch("matc_lut.bin")).arrayBuffer()),  // --lut raw --lut-precision f32
//     roughness: 0.3,
//   });
export function createMatcMaterial(THREE, { library, material, name, lut, roughness }) {
  // A default build's table holds a layer per basis side by side (the library says how many, and
  // each material's snippet samples its own layer: matc_lut_texcoord_<name>); --basis NAME, one.
  const layers = Number(/#define MATC_LUT_LAYERS (\d+)/.exec(library)?.[1] ?? 1);
  const size = Math.round(Math.sqrt(lut.length / 4 / layers));
  // RGBA float32 texels, roughness 0 in the first row; linear filtering of float32 textures needs
  // OES_texture_float_linear, which three.js enables when the device has it.
  const table = new THREE.DataTexture(lut, size * layers, size, THREE.RGBAFormat, THREE.FloatType);
  table.minFilter = THREE.LinearFilter;
  table.magFilter = THREE.LinearFilter;
  table.wrapS = THREE.ClampToEdgeWrapping;
  table.wrapT = THREE.ClampToEdgeWrapping;
  table.needsUpdate = true;
  return new THREE.ShaderMaterial({
    glslVersion: THREE.GLSL3,  // three.js writes "#version 300 es" and the precision statements
    uniforms: { matc_lut: { value: table }, matc_roughness: { value: roughness } },
    vertexShader: `
      out vec3 matc_normal;
      out vec3 matc_view;
      void main() {
        vec4 position_in_view = modelViewMatrix * vec4(position, 1.0);
        matc_normal = normalMatrix * normal;
        matc_view = -position_in_view.xyz;
        gl_Position = projectionMatrix * position_in_view;
      }`,
    fragmentShader: `precision highp sampler2D;
${library}
${material}
      uniform sampler2D matc_lut;
      uniform float matc_roughness;
      in vec3 matc_normal;
      in vec3 matc_view;
      out vec4 matc_color;
      void main() {
        float NdotV = clamp(dot(normalize(matc_normal), normalize(matc_view)), 0.0, 1.0);
#ifdef MATC_LUT_LAYERS
        vec4 bbar = texture(matc_lut, matc_lut_texcoord_${name}(NdotV, matc_roughness));
#else
        vec4 bbar = texture(matc_lut, matc_lut_texcoord(NdotV, matc_roughness));
#endif
        // Image-based specular for a white environment: Fbar with multiple scattering.
        vec3 specular = matc_fresnel_preintegrated_${name}(bbar) *
                        matc_energy_compensation(matc_coefficients_${name}, bbar);
        matc_color = vec4(specular, 1.0);
      }`,
  });
}
