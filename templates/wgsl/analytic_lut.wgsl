
// The preintegrated table in closed form, for shaders without a texture slot (docs/lut.md):
// bbar_i(NdotV, roughness) = sum of a_ipq T_p(x) T_q(y), Chebyshev polynomials of degree <= 11
// in polar coordinates (x, y) about the mirror-grazing corner; per channel 3x3 blocks of
// mat4x4f (block (A, B) holds p = 4A..4A+3 by column, q = 4B..4B+3). Fitted to the {{basis}}
// basis' 128x128 table by `matc basis analytic-lut`.
const MATC_ANALYTIC_LUT_MIN_U: f32 = 0.01;  // the table's bake clamps NdotV at 1e-4
{{analytic_lut_constants}}
fn matc_analytic_lut_channel(x0: vec4f, x1: vec4f, x2: vec4f, y0: vec4f, y1: vec4f, y2: vec4f,
                             m00: mat4x4f, m01: mat4x4f, m02: mat4x4f, m10: mat4x4f,
                             m11: mat4x4f, m12: mat4x4f, m20: mat4x4f, m21: mat4x4f,
                             m22: mat4x4f) -> f32 {
  return dot(x0, m00 * y0 + m01 * y1 + m02 * y2) + dot(x1, m10 * y0 + m11 * y1 + m12 * y2) +
         dot(x2, m20 * y0 + m21 * y1 + m22 * y2);
}

// bbar_0..bbar_3 at (NdotV, roughness) without a fetch: use it where a texel of matc_lut would
// be, with matc_fresnel_preintegrated and matc_energy_compensation.
fn matc_preintegrated_basis_analytic(NdotV: f32, roughness: f32) -> vec4f {
  let u = max(sqrt(clamp(NdotV, 0.0, 1.0)), MATC_ANALYTIC_LUT_MIN_U);
  let r = clamp(roughness, 0.0, 1.0);
  let x = sqrt(2.0 * (u * u + r * r)) - 1.0;
  let a = u * sqrt(u);
  let b = r * sqrt(r);
  let y = 2.0 * a / (a + b) - 1.0;
  // T_0..T_11 of x and y: T_2n = 2 T_n^2 - 1 and T_(m+k) = 2 T_m T_k - T_(m-k).
  let x0 = vec4f(1.0, x, 2.0 * x * x - 1.0, x * (4.0 * x * x - 3.0));
  let x4 = 2.0 * x0.z * x0.z - 1.0;
  let x1 = 2.0 * x4 * x0 - vec4f(x4, x0.wzy);
  let x8 = 2.0 * x4 * x4 - 1.0;
  let x2 = 2.0 * x8 * x0 - vec4f(x8, x1.wzy);
  let y0 = vec4f(1.0, y, 2.0 * y * y - 1.0, y * (4.0 * y * y - 3.0));
  let y4 = 2.0 * y0.z * y0.z - 1.0;
  let y1 = 2.0 * y4 * y0 - vec4f(y4, y0.wzy);
  let y8 = 2.0 * y4 * y4 - 1.0;
  let y2 = 2.0 * y8 * y0 - vec4f(y8, y1.wzy);
  return vec4f({{analytic_lut_channels}});
}
