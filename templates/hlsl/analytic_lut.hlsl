
// The preintegrated table in closed form, for shaders without a texture slot (docs/lut.md):
// bbar(NdotV, roughness) = E ((1 - t) b(mu_a) + t b(mu_b)), the GGX lobe's directional albedo E
// times a two-point quadrature of the basis over the lobe (nodes mu_a, mu_b, weight t of the
// second, clamped to [0, 1]), each a Chebyshev polynomial (total degree 12 for E, 6 for the
// quadrature) in polar coordinates (x, y) about the mirror-grazing corner. Fitted to the
// {{basis}} basis' 128x128 table by `matc basis analytic-lut`.
static const float MATC_ANALYTIC_LUT_MIN_U{{constant_suffix}} = 0.01;  // the table's bake clamps NdotV at 1e-4

// bbar_0..bbar_3 at (NdotV, roughness) without a fetch: use it where a texel of matc_lut would
// be, with matc_fresnel_preintegrated and matc_energy_compensation.
float4 matc_preintegrated_basis_analytic{{suffix}}(float NdotV, float roughness) {
  float u = max(sqrt(saturate(NdotV)), MATC_ANALYTIC_LUT_MIN_U{{constant_suffix}});
  float r = saturate(roughness);
  float x = sqrt(2.0 * (u * u + r * r)) - 1.0;
  float a = u * sqrt(u);
  float b = r * sqrt(r);
  float y = 2.0 * a / (a + b) - 1.0;
  // T_0..T_12 of x and y (T_k = 2 x T_(k-1) - T_(k-2)), then E, mu_a, mu_b and t.
{{analytic_lut_fields}}
  return albedo * lerp(matc_basis{{suffix}}(node_a), matc_basis{{suffix}}(node_b), saturate(weight_b));
}
