// matc {{version}}: the compute kernel that checks coated material {{name}} on a Vulkan device
// against the CPU runtime. For each query (mu, NdotV, roughness, -) it writes the base lobe's F
// (xyz) and the coat lobe's (w) at mu, then both preintegrated through the bound table and
// sampler, the embedded table (zero without one) and the closed form; the coat lobe is sampled
// at the coat's roughness. Fifth: a quad light of radiance 1 overhead (the shading frame: normal
// +z, view in the xz-plane at NdotV) on both lobes, through matc_ltc. Sixth: glTF's metal-rough
// mix under the coat (matc_metal_rough_{{name}}) of glTF's dielectric and the base lobe at mu,
// metalness = roughness, at NdotV (xyz), and the coat's transmission at NdotV (w).
{{library}}
{{material}}
[[vk::binding(0, 0)]] StructuredBuffer<float4> matc_queries : register(t0);
[[vk::binding(1, 0)]] RWStructuredBuffer<float4> matc_results : register(u1);
[[vk::binding(2, 0)]] Texture2D<float4> matc_lut : register(t2);
[[vk::binding(3, 0)]] SamplerState matc_lut_sampler : register(s3);
[[vk::binding(5, 0)]] Texture2D<float4> matc_ltc : register(t5);

float4 matc_lobes(float4 bbar, float4 coat_bbar, float NdotV) {
  return float4(matc_fresnel_preintegrated_{{name}}(bbar, coat_bbar, NdotV),
                matc_coat_fresnel_preintegrated_{{name}}(coat_bbar));
}

[numthreads(64, 1, 1)]
void main(uint3 id : SV_DispatchThreadID) {
  uint i = id.x;
  float4 query = matc_queries[i];
  float coat_roughness = matc_coat_roughness_{{name}};
  float4 bbar = matc_lut.SampleLevel(matc_lut_sampler, matc_lut_texcoord(query.y, query.z), 0.0);
  float4 coat_bbar =
      matc_lut.SampleLevel(matc_lut_sampler, matc_lut_texcoord(query.y, coat_roughness), 0.0);
  float4 embedded = 0.0;
#ifdef MATC_EMBEDDED_LUT_SIZE
  embedded = matc_lobes(matc_preintegrated_basis_embedded(query.y, query.z),
                        matc_preintegrated_basis_embedded(query.y, coat_roughness), query.y);
#endif
  float3 V = float3(sqrt(max(1.0 - query.y * query.y, 0.0)), 0.0, query.y);
  float4 ltc = matc_ltc.SampleLevel(matc_lut_sampler, matc_ltc_texcoord(query.y, query.z), 0.0);
  float4 coat_ltc =
      matc_ltc.SampleLevel(matc_lut_sampler, matc_ltc_texcoord(query.y, coat_roughness), 0.0);
  matc_results[6 * i] = float4(matc_fresnel_{{name}}(query.x), matc_coat_fresnel_{{name}}(query.x));
  matc_results[6 * i + 1] = matc_lobes(bbar, coat_bbar, query.y);
  matc_results[6 * i + 2] = embedded;
  matc_results[6 * i + 4] = float4(
      matc_ltc_quad_light_{{name}}(bbar, coat_bbar, ltc, coat_ltc, float3(0.0, 0.0, 1.0), V,
                                   float3(0.0, 0.0, 0.0), {{quad}}),
      1.0);
  matc_results[6 * i + 3] =
      matc_lobes(matc_preintegrated_basis_analytic(query.y, query.z),
                 matc_preintegrated_basis_analytic(query.y, coat_roughness), query.y);
  matc_results[6 * i + 5] =
      float4(matc_metal_rough_{{name}}(matc_dielectric_fresnel(float3(0.04, 0.04, 0.04),
                                                               float3(1.0, 1.0, 1.0), query.x),
                                       matc_fresnel_{{name}}(query.x), query.z, query.y),
             matc_coat_transmission_{{name}}(query.y));
}
