#version 450
// matc {{version}}: the compute kernel that checks the coefficient-table path (textured metals) on
// a Vulkan device against the CPU runtime. Each query is four vec4: (r.rgb, mu), (g.rgb, NdotV),
// (n.rgb, roughness), (k.rgb, -); it writes F(mu) and the preintegrated F from the (r, g)
// coefficients, F(mu) from the (n, k) ones through matc_artistic_from_ior, F(mu) from
// matc_coefficients_from_baked with F0 = r, c_2 = g - 0.5, c_3 = k / 8 - 0.5, and F(mu) from
// matc_coefficients_from_f0 with F0 = r on the same rows at F0 = 0.
{{library}}
layout(local_size_x = 64) in;
layout(std430, set = 0, binding = 0) readonly buffer MatcQueries { vec4 matc_queries[]; };
layout(std430, set = 0, binding = 1) writeonly buffer MatcResults { vec4 matc_results[]; };
layout(set = 0, binding = 2) uniform texture2D matc_lut;
layout(set = 0, binding = 3) uniform sampler matc_linear_sampler;
layout(set = 0, binding = 4) uniform texture2D matc_coefficient_table;

void main() {
  uint i = gl_GlobalInvocationID.x;
  vec4 reflectivity_mu = matc_queries[4u * i];
  vec4 edge_tint_ndotv = matc_queries[4u * i + 1u];
  vec4 n_roughness = matc_queries[4u * i + 2u];
  vec4 k = matc_queries[4u * i + 3u];
  vec3 r = reflectivity_mu.xyz;
  vec3 g = edge_tint_ndotv.xyz;
  MatcFresnelCoefficients c = MATC_COEFFICIENTS_FROM_TABLE(
      sampler2D(matc_coefficient_table, matc_linear_sampler), r, g);
  vec4 bbar = textureLod(sampler2D(matc_lut, matc_linear_sampler),
                         matc_lut_texcoord(edge_tint_ndotv.w, n_roughness.w), 0.0);
  MatcArtistic artistic = matc_artistic_from_ior(n_roughness.xyz, k.xyz);
  vec3 ior_r = artistic.reflectivity;
  vec3 ior_g = artistic.edge_tint;
  MatcFresnelCoefficients from_ior = MATC_COEFFICIENTS_FROM_TABLE(
      sampler2D(matc_coefficient_table, matc_linear_sampler), ior_r, ior_g);
  MatcFresnelCoefficients baked =
      matc_coefficients_from_baked(r, g - 0.5, k.xyz * 0.125 - 0.5);
  matc_results[5u * i] = vec4(matc_fresnel(c, reflectivity_mu.w), 1.0);
  matc_results[5u * i + 1u] = vec4(matc_fresnel_preintegrated(c, bbar), 1.0);
  matc_results[5u * i + 2u] = vec4(matc_fresnel(from_ior, reflectivity_mu.w), 1.0);
  matc_results[5u * i + 3u] = vec4(matc_fresnel(baked, reflectivity_mu.w), 1.0);
  // Per pixel from F0 = r, on rows at F0 = 0 of (0, 1, g - 0.5, k / 8 - 0.5).
  MatcFresnelCoefficients from_f0 = matc_coefficients_from_f0(
      matc_coefficients_from_baked(vec3(0.0), g - 0.5, k.xyz * 0.125 - 0.5), r);
  matc_results[5u * i + 4u] = vec4(matc_fresnel(from_f0, reflectivity_mu.w), 1.0);
}
