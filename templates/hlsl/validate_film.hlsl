// matc {{version}}: the compute kernel that checks filmed material {{name}} on a Vulkan device
// against the CPU runtime. For each query (mu, NdotV, roughness, thickness) it writes F(mu) and
// the preintegrated F at (NdotV, roughness), both from the film's table (binding 6) through the
// table sampler (a thickness per pixel: at the thickness coordinate), then a quad light of
// radiance 1 overhead (the shading frame: normal +z, view in the xz-plane at NdotV) through
// matc_ltc.
{{library}}
{{material}}
[[vk::binding(0, 0)]] StructuredBuffer<float4> matc_queries : register(t0);
[[vk::binding(1, 0)]] RWStructuredBuffer<float4> matc_results : register(u1);
[[vk::binding(3, 0)]] SamplerState matc_lut_sampler : register(s3);
[[vk::binding(5, 0)]] Texture2D<float4> matc_ltc : register(t5);
[[vk::binding(6, 0)]] Texture2D<float4> matc_film : register(t6);

[numthreads(64, 1, 1)]
void main(uint3 id : SV_DispatchThreadID) {
  uint i = id.x;
  float4 query = matc_queries[i];
  float4 direct = {{film_direct}};
  float4 image = {{film_image}};
  float3 V = float3(sqrt(max(1.0 - query.y * query.y, 0.0)), 0.0, query.y);
  float4 ltc = matc_ltc.SampleLevel(matc_lut_sampler, matc_ltc_texcoord(query.y, query.z), 0.0);
  matc_results[3 * i] = float4(matc_fresnel_{{name}}(direct), 1.0);
  matc_results[3 * i + 1] = float4(matc_fresnel_preintegrated_{{name}}(image), 1.0);
  matc_results[3 * i + 2] = float4(
      matc_ltc_quad_light_{{name}}(image, ltc, float3(0.0, 0.0, 1.0), V, float3(0.0, 0.0, 0.0), {{quad}}),
      1.0);
}
