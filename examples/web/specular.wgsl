// Image-based specular with matc's Fresnel in WGSL: one shader module holds matc_fresnel.wgsl,
// gold.wgsl and this. matc_lut is matc_lut.bin (--lut raw --lut-precision f16) as rgba16float,
// a layer per basis side by side (256x128), sampled linearly with clamp-to-edge at the material's
// own layer. Tested on Dawn by tests/js/check-webgpu.mjs.
@group(0) @binding(2) var matc_lut: texture_2d<f32>;
@group(0) @binding(5) var matc_linear: sampler;

fn specular_gold(NdotV: f32, roughness: f32) -> vec3f {
  let bbar = textureSampleLevel(matc_lut, matc_linear, matc_lut_texcoord_gold(NdotV, roughness), 0.0);
  return matc_fresnel_preintegrated_gold(bbar) *
         matc_energy_compensation(matc_coefficients_gold, bbar);
}
