
// The preintegrated table itself ({{embedded_size}}x{{embedded_size}}, --embed-lut){{of_basis}}, for shaders
// that cannot bind one more texture: row-major texels bbar_0..bbar_3, same axes as matc_lut.*.
#define MATC_EMBEDDED_LUT_SIZE{{suffix}} {{embedded_size}}
static const float4 MATC_EMBEDDED_LUT{{suffix}}[{{embedded_texels}}] = {
{{embedded_texel_values}}};

float4 matc_embedded_lut_texel{{suffix}}(int x, int y) {
  return MATC_EMBEDDED_LUT{{suffix}}[y * MATC_EMBEDDED_LUT_SIZE{{suffix}} + x];
}

// bbar_0..bbar_3 at (NdotV, roughness), filtered bilinearly by hand as a sampler would.
float4 matc_preintegrated_basis_embedded{{suffix}}(float NdotV, float roughness) {
  float2 position = float2(sqrt(saturate(NdotV)), saturate(roughness)) *
                    float(MATC_EMBEDDED_LUT_SIZE{{suffix}} - 1);
  int2 corner = min(int2(position), int2(MATC_EMBEDDED_LUT_SIZE{{suffix}} - 2, MATC_EMBEDDED_LUT_SIZE{{suffix}} - 2));
  float2 f = position - float2(corner);
  float4 bottom = lerp(matc_embedded_lut_texel{{suffix}}(corner.x, corner.y),
                       matc_embedded_lut_texel{{suffix}}(corner.x + 1, corner.y), f.x);
  float4 top = lerp(matc_embedded_lut_texel{{suffix}}(corner.x, corner.y + 1),
                    matc_embedded_lut_texel{{suffix}}(corner.x + 1, corner.y + 1), f.x);
  return lerp(bottom, top, f.y);
}
