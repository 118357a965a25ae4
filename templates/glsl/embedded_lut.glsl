
// The preintegrated table itself ({{embedded_size}}x{{embedded_size}}, --embed-lut){{of_basis}}, for shaders
// that cannot bind one more texture: row-major texels bbar_0..bbar_3, same axes as matc_lut.*.
#define MATC_EMBEDDED_LUT_SIZE{{suffix}} {{embedded_size}}
const vec4 MATC_EMBEDDED_LUT{{suffix}}[{{embedded_texels}}] = vec4[{{embedded_texels}}](
{{embedded_texel_values}});

vec4 matc_embedded_lut_texel{{suffix}}(int x, int y) {
  return MATC_EMBEDDED_LUT{{suffix}}[y * MATC_EMBEDDED_LUT_SIZE{{suffix}} + x];
}

// bbar_0..bbar_3 at (NdotV, roughness), filtered bilinearly by hand as a sampler would.
vec4 matc_preintegrated_basis_embedded{{suffix}}(float NdotV, float roughness) {
  vec2 position = vec2(sqrt(clamp(NdotV, 0.0, 1.0)), clamp(roughness, 0.0, 1.0)) *
                  float(MATC_EMBEDDED_LUT_SIZE{{suffix}} - 1);
  ivec2 corner = min(ivec2(position), ivec2(MATC_EMBEDDED_LUT_SIZE{{suffix}} - 2));
  vec2 f = position - vec2(corner);
  vec4 bottom = mix(matc_embedded_lut_texel{{suffix}}(corner.x, corner.y),
                    matc_embedded_lut_texel{{suffix}}(corner.x + 1, corner.y), f.x);
  vec4 top = mix(matc_embedded_lut_texel{{suffix}}(corner.x, corner.y + 1),
                 matc_embedded_lut_texel{{suffix}}(corner.x + 1, corner.y + 1), f.x);
  return mix(bottom, top, f.y);
}
