#version 450
// matc {{version}}: the compute kernel that checks the area-light functions on a Vulkan device
// against the CPU runtime. Each query is eight vec4: (r.rgb, NdotV), (g.rgb, roughness),
// (N, kind), (V, radius), then a quad's four corners (kind 0), a disk's centre and normal
// (kind 1) or a sphere's centre (kind 2), world space, shading point at the origin; it writes the radiance and
// I_ltc, then the quality level's radiance (shape and Fresnel following the light).
{{library}}
layout(local_size_x = 64) in;
layout(std430, set = 0, binding = 0) readonly buffer MatcQueries { vec4 matc_queries[]; };
layout(std430, set = 0, binding = 1) writeonly buffer MatcResults { vec4 matc_results[]; };
layout(set = 0, binding = 2) uniform texture2D matc_lut;
layout(set = 0, binding = 3) uniform sampler matc_linear_sampler;
layout(set = 0, binding = 4) uniform texture2D matc_coefficient_table;
layout(set = 0, binding = 5) uniform texture2D matc_ltc;

void main() {
  uint i = gl_GlobalInvocationID.x;
  vec4 q[8];
  for (uint k = 0u; k < 8u; ++k)
    q[k] = matc_queries[8u * i + k];
  MatcFresnelCoefficients c = MATC_COEFFICIENTS_FROM_TABLE(
      sampler2D(matc_coefficient_table, matc_linear_sampler), q[0].xyz, q[1].xyz);
  float ndotv = q[0].w;
  float roughness = q[1].w;
  vec4 bbar = textureLod(sampler2D(matc_lut, matc_linear_sampler),
                         matc_lut_texcoord(ndotv, roughness), 0.0);
  vec4 ltc = textureLod(sampler2D(matc_ltc, matc_linear_sampler),
                        matc_ltc_texcoord(ndotv, roughness), 0.0);
  vec3 N = q[2].xyz;
  vec3 V = q[3].xyz;
  vec3 P = vec3(0.0);
  vec3 radiance;
  float integral;
  vec3 following;
  if (q[2].w == 0.0) {
    radiance = matc_ltc_quad_light(c, bbar, ltc, N, V, P, q[4].xyz, q[5].xyz, q[6].xyz, q[7].xyz);
    following = matc_ltc_quad_light_following(c, bbar, ltc, roughness, N, V, P, q[4].xyz, q[5].xyz, q[6].xyz,
                                              q[7].xyz);
    integral =
        matc_ltc_quad_integral(matc_ltc_transform(N, V, ltc), P, q[4].xyz, q[5].xyz, q[6].xyz,
                               q[7].xyz);
  } else if (q[2].w == 1.0) {
    radiance = matc_ltc_disk_light(c, bbar, ltc, N, V, P, q[4].xyz, q[5].xyz, q[3].w);
    following = matc_ltc_disk_light_following(c, bbar, ltc, roughness, N, V, P, q[4].xyz, q[5].xyz, q[3].w);
    integral = matc_ltc_disk_integral(matc_ltc_transform(N, V, ltc), P, q[4].xyz, q[5].xyz, q[3].w);
  } else {
    radiance = matc_ltc_sphere_light(c, bbar, ltc, N, V, P, q[4].xyz, q[3].w);
    following = matc_ltc_sphere_light_following(c, bbar, ltc, roughness, N, V, P, q[4].xyz, q[3].w);
    integral = matc_ltc_sphere_integral(matc_ltc_transform(N, V, ltc), P, q[4].xyz, q[3].w);
  }
  matc_results[2u * i] = vec4(radiance, integral);
  matc_results[2u * i + 1u] = vec4(following, 0.0);
}
