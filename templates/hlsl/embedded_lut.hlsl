
// The preintegrated table itself ({{embedded_size}}x{{embedded_size}}, --embed-lut), for shaders
// that cannot bind one more texture: row-major texels bbar_0..bbar_3, same axes as matc_lut.*.
#define MATC_EMBEDDED_LUT_SIZE {{embedded_size}}
static const float4 MATC_EMBEDDED_LUT[{{embedded_texels}}] = {
{{embedded_texel_values}}};

float4 matc_embedded_lut_texel(int x, int y) {
  return MATC_EMBEDDED_LUT[y * MATC_EMBEDDED_LUT_SIZE + x];
}

// bbar_0..bbar_3 at (NdotV, roughness), filtered bilinearly by hand as a sampler would.
float4 matc_preintegrated_basis_embedded(float NdotV, float roughness) {
  float2 position = float2(sqrt(saturate(NdotV)), saturate(roughness)) *
                    float(MATC_EMBEDDED_LUT_SIZE - 1);
  int2 corner = min(int2(position), int2(MATC_EMBEDDED_LUT_SIZE - 2, MATC_EMBEDDED_LUT_SIZE - 2));
  float2 f = position - float2(corner);
  float4 bottom = lerp(matc_embedded_lut_texel(corner.x, corner.y),
                       matc_embedded_lut_texel(corner.x + 1, corner.y), f.x);
  float4 top = lerp(matc_embedded_lut_texel(corner.x, corner.y + 1),
                    matc_embedded_lut_texel(corner.x + 1, corner.y + 1), f.x);
  return lerp(bottom, top, f.y);
}
