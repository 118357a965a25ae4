// matc {{version}}: the compute kernel that checks material {{name}}, a filmed metal under a coat,
// on a Vulkan device against the CPU runtime. For each query (mu, NdotV, roughness, -) it writes
// the base lobe's F (xyz, from the film's table at binding 6) and the coat lobe's (w) at mu, then
// both preintegrated (the base's from the film's table at (NdotV, roughness), the coat's from
// matc_lut at the coat's roughness), then a quad light of radiance 1 overhead (the shading frame:
// normal +z, view in the xz-plane at NdotV) on both lobes through matc_ltc, then glTF's
// metal-rough mix under the coat (matc_metal_rough_{{name}}) of glTF's dielectric and the base
// lobe at mu, metalness = roughness, at NdotV (xyz), and the coat's transmission at NdotV (w).
{{library}}
{{material}}
[[vk::binding(0, 0)]] StructuredBuffer<float4> matc_queries : register(t0);
[[vk::binding(1, 0)]] RWStructuredBuffer<float4> matc_results : register(u1);
[[vk::binding(2, 0)]] Texture2D<float4> matc_lut : register(t2);
[[vk::binding(3, 0)]] SamplerState matc_lut_sampler : register(s3);
[[vk::binding(5, 0)]] Texture2D<float4> matc_ltc : register(t5);
[[vk::binding(6, 0)]] Texture2D<float4> matc_film : register(t6);

[numthreads(64, 1, 1)]
void main(uint3 id : SV_DispatchThreadID) {
  uint i = id.x;
  float4 query = matc_queries[i];
  float coat_roughness = matc_coat_roughness_{{name}};
  float4 direct = matc_film_fresnel(matc_film, matc_lut_sampler, query.x);
  float4 image = matc_film_preintegrated(matc_film, matc_lut_sampler, query.y, query.z);
  float4 coat_bbar =
      matc_lut.SampleLevel(matc_lut_sampler, matc_lut_texcoord(query.y, coat_roughness), 0.0);
  float3 V = float3(sqrt(max(1.0 - query.y * query.y, 0.0)), 0.0, query.y);
  float4 ltc = matc_ltc.SampleLevel(matc_lut_sampler, matc_ltc_texcoord(query.y, query.z), 0.0);
  float4 coat_ltc =
      matc_ltc.SampleLevel(matc_lut_sampler, matc_ltc_texcoord(query.y, coat_roughness), 0.0);
  matc_results[4 * i] = float4(matc_fresnel_{{name}}(direct), matc_coat_fresnel_{{name}}(query.x));
  matc_results[4 * i + 1] = float4(matc_fresnel_preintegrated_{{name}}(image),
                                   matc_coat_fresnel_preintegrated_{{name}}(coat_bbar));
  matc_results[4 * i + 2] = float4(
      matc_ltc_quad_light_{{name}}(image, coat_bbar, ltc, coat_ltc, float3(0.0, 0.0, 1.0), V,
                                   float3(0.0, 0.0, 0.0), {{quad}}),
      1.0);
  matc_results[4 * i + 3] =
      float4(matc_metal_rough_{{name}}(matc_dielectric_fresnel(float3(0.04, 0.04, 0.04),
                                                               float3(1.0, 1.0, 1.0), query.x),
                                       matc_fresnel_{{name}}(direct), query.z, query.y),
             matc_coat_transmission_{{name}}(query.y));
}
