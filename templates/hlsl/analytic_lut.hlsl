
// The preintegrated table in closed form, for shaders without a texture slot (docs/lut.md):
// bbar_i(NdotV, roughness) = sum of a_ipq T_p(x) T_q(y), Chebyshev polynomials of degree <= 11
// in polar coordinates (x, y) about the mirror-grazing corner; per channel 3x3 blocks of
// float4x4 (block (A, B) holds p = 4A..4A+3 by row, q = 4B..4B+3). Fitted to the {{basis}}
// basis' 128x128 table by `matc basis analytic-lut`.
static const float MATC_ANALYTIC_LUT_MIN_U = 0.01;  // the table's bake clamps NdotV at 1e-4
{{analytic_lut_constants}}
float matc_analytic_lut_channel(float4 x0, float4 x1, float4 x2, float4 y0, float4 y1,
                                float4 y2, float4x4 m00, float4x4 m01, float4x4 m02,
                                float4x4 m10, float4x4 m11, float4x4 m12, float4x4 m20,
                                float4x4 m21, float4x4 m22) {
  return dot(x0, mul(m00, y0) + mul(m01, y1) + mul(m02, y2)) +
         dot(x1, mul(m10, y0) + mul(m11, y1) + mul(m12, y2)) +
         dot(x2, mul(m20, y0) + mul(m21, y1) + mul(m22, y2));
}

// bbar_0..bbar_3 at (NdotV, roughness) without a fetch: use it where a texel of matc_lut would
// be, with matc_fresnel_preintegrated and matc_energy_compensation.
float4 matc_preintegrated_basis_analytic(float NdotV, float roughness) {
  float u = max(sqrt(saturate(NdotV)), MATC_ANALYTIC_LUT_MIN_U);
  float r = saturate(roughness);
  float x = sqrt(2.0 * (u * u + r * r)) - 1.0;
  float a = u * sqrt(u);
  float b = r * sqrt(r);
  float y = 2.0 * a / (a + b) - 1.0;
  // T_0..T_11 of x and y: T_2n = 2 T_n^2 - 1 and T_(m+k) = 2 T_m T_k - T_(m-k).
  float4 x0 = float4(1.0, x, 2.0 * x * x - 1.0, x * (4.0 * x * x - 3.0));
  float x4 = 2.0 * x0.z * x0.z - 1.0;
  float4 x1 = 2.0 * x4 * x0 - float4(x4, x0.wzy);
  float x8 = 2.0 * x4 * x4 - 1.0;
  float4 x2 = 2.0 * x8 * x0 - float4(x8, x1.wzy);
  float4 y0 = float4(1.0, y, 2.0 * y * y - 1.0, y * (4.0 * y * y - 3.0));
  float y4 = 2.0 * y0.z * y0.z - 1.0;
  float4 y1 = 2.0 * y4 * y0 - float4(y4, y0.wzy);
  float y8 = 2.0 * y4 * y4 - 1.0;
  float4 y2 = 2.0 * y8 * y0 - float4(y8, y1.wzy);
  return float4({{analytic_lut_channels}});
}
