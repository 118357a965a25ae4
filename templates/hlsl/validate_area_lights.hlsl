// matc {{version}}: the compute kernel that checks the area-light functions on a Vulkan device
// against the CPU runtime. Each query is eight float4: (r.rgb, NdotV), (g.rgb, roughness),
// (N, kind), (V, radius), then a quad's four corners (kind 0), a disk's centre and normal
// (kind 1) or a sphere's centre (kind 2), world space, shading point at the origin; it writes the radiance and
// I_ltc, then the quality level's radiance (shape and Fresnel following the light).
{{library}}
[[vk::binding(0, 0)]] StructuredBuffer<float4> matc_queries : register(t0);
[[vk::binding(1, 0)]] RWStructuredBuffer<float4> matc_results : register(u1);
[[vk::binding(2, 0)]] Texture2D<float4> matc_lut : register(t2);
[[vk::binding(3, 0)]] SamplerState matc_linear_sampler : register(s3);
[[vk::binding(4, 0)]] Texture2D<float4> matc_coefficient_table : register(t4);
[[vk::binding(5, 0)]] Texture2D<float4> matc_ltc : register(t5);

[numthreads(64, 1, 1)]
void main(uint3 id : SV_DispatchThreadID) {
  uint i = id.x;
  float4 q[8];
  for (uint k = 0; k < 8; ++k)
    q[k] = matc_queries[8 * i + k];
  MatcFresnelCoefficients c =
      MATC_COEFFICIENTS_FROM_TABLE(matc_coefficient_table, matc_linear_sampler, q[0].xyz, q[1].xyz);
  float ndotv = q[0].w;
  float roughness = q[1].w;
  float4 bbar = matc_lut.SampleLevel(matc_linear_sampler, matc_lut_texcoord(ndotv, roughness), 0.0);
  float4 ltc = matc_ltc.SampleLevel(matc_linear_sampler, matc_ltc_texcoord(ndotv, roughness), 0.0);
  float3 N = q[2].xyz;
  float3 V = q[3].xyz;
  float3 P = float3(0.0, 0.0, 0.0);
  float3 radiance;
  float integral;
  float3 following;
  if (q[2].w == 0.0) {
    radiance = matc_ltc_quad_light(c, bbar, ltc, N, V, P, q[4].xyz, q[5].xyz, q[6].xyz, q[7].xyz);
    following = matc_ltc_quad_light_following(c, bbar, ltc, roughness, N, V, P, q[4].xyz, q[5].xyz, q[6].xyz,
                                              q[7].xyz);
    integral = matc_ltc_quad_integral(matc_ltc_transform(N, V, ltc), P, q[4].xyz, q[5].xyz,
                                      q[6].xyz, q[7].xyz);
  } else if (q[2].w == 1.0) {
    radiance = matc_ltc_disk_light(c, bbar, ltc, N, V, P, q[4].xyz, q[5].xyz, q[3].w);
    following = matc_ltc_disk_light_following(c, bbar, ltc, roughness, N, V, P, q[4].xyz, q[5].xyz, q[3].w);
    integral =
        matc_ltc_disk_integral(matc_ltc_transform(N, V, ltc), P, q[4].xyz, q[5].xyz, q[3].w);
  } else {
    radiance = matc_ltc_sphere_light(c, bbar, ltc, N, V, P, q[4].xyz, q[3].w);
    following = matc_ltc_sphere_light_following(c, bbar, ltc, roughness, N, V, P, q[4].xyz, q[3].w);
    integral = matc_ltc_sphere_integral(matc_ltc_transform(N, V, ltc), P, q[4].xyz, q[3].w);
  }
  matc_results[2 * i] = float4(radiance, integral);
  matc_results[2 * i + 1] = float4(following, 0.0);
}
