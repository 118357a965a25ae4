// matc {{version}}: the compute kernel that checks material {{name}} on a Vulkan device against the
// CPU runtime. For each query (mu, NdotV, roughness, -) it writes F(mu), the preintegrated F
// through the bound table and sampler, the same from the embedded table (zero without one) and
// from the closed form (matc_preintegrated_basis_analytic).
{{library}}
{{material}}
[[vk::binding(0, 0)]] StructuredBuffer<float4> matc_queries : register(t0);
[[vk::binding(1, 0)]] RWStructuredBuffer<float4> matc_results : register(u1);
[[vk::binding(2, 0)]] Texture2D<float4> matc_lut : register(t2);
[[vk::binding(3, 0)]] SamplerState matc_lut_sampler : register(s3);

[numthreads(64, 1, 1)]
void main(uint3 id : SV_DispatchThreadID) {
  uint i = id.x;
  float4 query = matc_queries[i];
  float4 bbar = matc_lut.SampleLevel(matc_lut_sampler, matc_lut_texcoord{{suffix}}(query.y, query.z), 0.0);
  float4 embedded = 0.0;
#ifdef MATC_EMBEDDED_LUT_SIZE
  embedded = float4(matc_fresnel_preintegrated_{{name}}(
                        matc_preintegrated_basis_embedded{{suffix}}(query.y, query.z)), 1.0);
#endif
  matc_results[4 * i] = float4(matc_fresnel_{{name}}(query.x), 1.0);
  matc_results[4 * i + 1] = float4(matc_fresnel_preintegrated_{{name}}(bbar), 1.0);
  matc_results[4 * i + 2] = embedded;
  matc_results[4 * i + 3] = float4(matc_fresnel_preintegrated_{{name}}(
                                       matc_preintegrated_basis_analytic{{suffix}}(query.y, query.z)), 1.0);
}
