// matc {{version}}: the compute kernel that checks the coefficient-table path (textured metals) on
// a Vulkan device against the CPU runtime. Each query is four float4: (r.rgb, mu),
// (g.rgb, NdotV), (n.rgb, roughness), (k.rgb, -); it writes F(mu) and the preintegrated F from
// the (r, g) coefficients, F(mu) from the (n, k) ones through matc_artistic_from_ior, F(mu) from
// matc_coefficients_from_baked with F0 = r, c_2 = g - 0.5, c_3 = k / 8 - 0.5, and F(mu) from
// matc_coefficients_from_f0 with F0 = r on the same rows at F0 = 0, and F(mu) from an F0 table
// at F0 = r, in air and under a coat, whose entry i of channel c is matc_check_f0_entry(i, c),
// and glTF's metal-rough mix of the (r, g) metal with a dielectric (matc_metal_rough).
{{library}}
[[vk::binding(0, 0)]] StructuredBuffer<float4> matc_queries : register(t0);
[[vk::binding(1, 0)]] RWStructuredBuffer<float4> matc_results : register(u1);
[[vk::binding(2, 0)]] Texture2D<float4> matc_lut : register(t2);
[[vk::binding(3, 0)]] SamplerState matc_linear_sampler : register(s3);
[[vk::binding(4, 0)]] Texture2D<float4> matc_coefficient_table : register(t4);

// A table of the query's values, not linear in i (so that the wrong pair of entries shows).
float4 matc_check_f0_entry(int i, float3 g, float3 n, float3 k, int c) {
  float s = float(i * i) / 1024.0;
  return float4(g[c], k[c] * 0.125, g[c] - 0.5, k[c] * 0.125 - 0.5) +
         s * float4(n[c] * 0.25, 0.5 - g[c], 1.0 - g[c], k[c] * 0.125 - 0.25);
}
MatcFresnelCoefficients matc_check_f0_entries(float3 f0, int next, float3 g, float3 n, float3 k) {
  MatcFresnelCoefficients c;
  c.red = matc_check_f0_entry(matc_f0_table_left(matc_f0_table_position(f0.x)) + next, g, n, k, 0);
  c.green = matc_check_f0_entry(matc_f0_table_left(matc_f0_table_position(f0.y)) + next, g, n, k, 1);
  c.blue = matc_check_f0_entry(matc_f0_table_left(matc_f0_table_position(f0.z)) + next, g, n, k, 2);
  return c;
}

[numthreads(64, 1, 1)]
void main(uint3 id : SV_DispatchThreadID) {
  uint i = id.x;
  float4 reflectivity_mu = matc_queries[4 * i];
  float4 edge_tint_ndotv = matc_queries[4 * i + 1];
  float4 n_roughness = matc_queries[4 * i + 2];
  float4 k = matc_queries[4 * i + 3];
  float3 r = reflectivity_mu.xyz;
  float3 g = edge_tint_ndotv.xyz;
  MatcFresnelCoefficients c =
      MATC_COEFFICIENTS_FROM_TABLE(matc_coefficient_table, matc_linear_sampler, r, g);
  float4 bbar = matc_lut.SampleLevel(matc_linear_sampler,
                                     matc_lut_texcoord(edge_tint_ndotv.w, n_roughness.w), 0.0);
  MatcArtistic artistic = matc_artistic_from_ior(n_roughness.xyz, k.xyz);
  float3 ior_r = artistic.reflectivity;
  float3 ior_g = artistic.edge_tint;
  MatcFresnelCoefficients from_ior =
      MATC_COEFFICIENTS_FROM_TABLE(matc_coefficient_table, matc_linear_sampler, ior_r, ior_g);
  MatcFresnelCoefficients baked =
      matc_coefficients_from_baked(r, g - 0.5, k.xyz * 0.125 - 0.5);
  matc_results[8 * i] = float4(matc_fresnel(c, reflectivity_mu.w), 1.0);
  matc_results[8 * i + 1] = float4(matc_fresnel_preintegrated(c, bbar), 1.0);
  matc_results[8 * i + 2] = float4(matc_fresnel(from_ior, reflectivity_mu.w), 1.0);
  matc_results[8 * i + 3] = float4(matc_fresnel(baked, reflectivity_mu.w), 1.0);
  // Per pixel from F0 = r, on rows at F0 = 0 of (0, 1, g - 0.5, k / 8 - 0.5).
  MatcFresnelCoefficients from_f0 = matc_coefficients_from_f0(
      matc_coefficients_from_baked(float3(0.0, 0.0, 0.0), g - 0.5, k.xyz * 0.125 - 0.5), r);
  matc_results[8 * i + 4] = float4(matc_fresnel(from_f0, reflectivity_mu.w), 1.0);
  MatcFresnelCoefficients left = matc_check_f0_entries(r, 0, g, n_roughness.xyz, k.xyz);
  MatcFresnelCoefficients right = matc_check_f0_entries(r, 1, g, n_roughness.xyz, k.xyz);
  MatcFresnelCoefficients in_air = matc_coefficients_from_f0_entries(r, left, right);
  MatcFresnelCoefficients under_coat = matc_under_coat_from_f0_entries(r, left, right);
  matc_results[8 * i + 5] = float4(matc_fresnel(in_air, reflectivity_mu.w), 1.0);
  matc_results[8 * i + 6] = float4(matc_fresnel(under_coat, reflectivity_mu.w), 1.0);
  // glTF's metal-rough mix: the (r, g) metal with a dielectric of F0 g * 0.08 and F90 NdotV, by
  // metalness = roughness.
  float3 dielectric =
      matc_dielectric_fresnel(g * 0.08, float3(1.0, 1.0, 1.0) * edge_tint_ndotv.w, reflectivity_mu.w);
  matc_results[8 * i + 7] = float4(
      matc_metal_rough(dielectric, matc_fresnel(c, reflectivity_mu.w), n_roughness.w), 1.0);
}
