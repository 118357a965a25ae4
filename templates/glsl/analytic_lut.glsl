
// The preintegrated table in closed form, for shaders without a texture slot (docs/lut.md):
// bbar_i(NdotV, roughness) = sum of a_ipq T_p(x) T_q(y), Chebyshev polynomials of degree <= 11
// in polar coordinates (x, y) about the mirror-grazing corner; per channel 3x3 blocks of mat4
// (block (A, B) holds p = 4A..4A+3 by column, q = 4B..4B+3). Fitted to the {{basis}} basis'
// 128x128 table by `matc basis analytic-lut`.
const float MATC_ANALYTIC_LUT_MIN_U = 0.01;  // the table's bake clamps NdotV at 1e-4
{{analytic_lut_constants}}
float matc_analytic_lut_channel(vec4 x0, vec4 x1, vec4 x2, vec4 y0, vec4 y1, vec4 y2, mat4 m00,
                                mat4 m01, mat4 m02, mat4 m10, mat4 m11, mat4 m12, mat4 m20,
                                mat4 m21, mat4 m22) {
  return dot(x0, m00 * y0 + m01 * y1 + m02 * y2) + dot(x1, m10 * y0 + m11 * y1 + m12 * y2) +
         dot(x2, m20 * y0 + m21 * y1 + m22 * y2);
}

// bbar_0..bbar_3 at (NdotV, roughness) without a fetch: use it where a texel of matc_lut would
// be, with matc_fresnel_preintegrated and matc_energy_compensation.
vec4 matc_preintegrated_basis_analytic(float NdotV, float roughness) {
  float u = max(sqrt(clamp(NdotV, 0.0, 1.0)), MATC_ANALYTIC_LUT_MIN_U);
  float r = clamp(roughness, 0.0, 1.0);
  float x = sqrt(2.0 * (u * u + r * r)) - 1.0;
  float a = u * sqrt(u);
  float b = r * sqrt(r);
  float y = 2.0 * a / (a + b) - 1.0;
  // T_0..T_11 of x and y: T_2n = 2 T_n^2 - 1 and T_(m+k) = 2 T_m T_k - T_(m-k).
  vec4 x0 = vec4(1.0, x, 2.0 * x * x - 1.0, x * (4.0 * x * x - 3.0));
  float x4 = 2.0 * x0.z * x0.z - 1.0;
  vec4 x1 = 2.0 * x4 * x0 - vec4(x4, x0.wzy);
  float x8 = 2.0 * x4 * x4 - 1.0;
  vec4 x2 = 2.0 * x8 * x0 - vec4(x8, x1.wzy);
  vec4 y0 = vec4(1.0, y, 2.0 * y * y - 1.0, y * (4.0 * y * y - 3.0));
  float y4 = 2.0 * y0.z * y0.z - 1.0;
  vec4 y1 = 2.0 * y4 * y0 - vec4(y4, y0.wzy);
  float y8 = 2.0 * y4 * y4 - 1.0;
  vec4 y2 = 2.0 * y8 * y0 - vec4(y8, y1.wzy);
  return vec4({{analytic_lut_channels}});
}
