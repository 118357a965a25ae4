#version 450
// matc {{version}}: the compute kernel that checks the coefficient-table path (textured metals) on
// a Vulkan device against the CPU runtime. Each query is four vec4: (r.rgb, mu), (g.rgb, NdotV),
// (n.rgb, roughness), (k.rgb, -); it writes F(mu) and the preintegrated F from the (r, g)
// coefficients, F(mu) from the (n, k) ones through matc_artistic_from_ior, F(mu) from
// matc_coefficients_from_baked with F0 = r, c_2 = g - 0.5, c_3 = k / 8 - 0.5, and F(mu) from
// matc_coefficients_from_f0 with F0 = r on the same rows at F0 = 0, and F(mu) from an F0 table
// at F0 = r, in air and under a coat, whose entry i of channel c is matc_check_f0_entry(i, c),
// and glTF's metal-rough mix of the (r, g) metal with a dielectric (matc_metal_rough).
{{library}}
layout(local_size_x = 64) in;
layout(std430, set = 0, binding = 0) readonly buffer MatcQueries { vec4 matc_queries[]; };
layout(std430, set = 0, binding = 1) writeonly buffer MatcResults { vec4 matc_results[]; };
layout(set = 0, binding = 2) uniform texture2D matc_lut;
layout(set = 0, binding = 3) uniform sampler matc_linear_sampler;
layout(set = 0, binding = 4) uniform texture2D matc_coefficient_table;

// A table of the query's values, not linear in i (so that the wrong pair of entries shows).
vec4 matc_check_f0_entry(int i, vec3 g, vec3 n, vec3 k, int c) {
  float s = float(i * i) / 1024.0;
  return vec4(g[c], k[c] * 0.125, g[c] - 0.5, k[c] * 0.125 - 0.5) +
         s * vec4(n[c] * 0.25, 0.5 - g[c], 1.0 - g[c], k[c] * 0.125 - 0.25);
}
MatcFresnelCoefficients matc_check_f0_entries(vec3 f0, int next, vec3 g, vec3 n, vec3 k) {
  return MatcFresnelCoefficients(
      matc_check_f0_entry(matc_f0_table_left(matc_f0_table_position(f0.x)) + next, g, n, k, 0),
      matc_check_f0_entry(matc_f0_table_left(matc_f0_table_position(f0.y)) + next, g, n, k, 1),
      matc_check_f0_entry(matc_f0_table_left(matc_f0_table_position(f0.z)) + next, g, n, k, 2));
}

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
  matc_results[8u * i] = vec4(matc_fresnel(c, reflectivity_mu.w), 1.0);
  matc_results[8u * i + 1u] = vec4(matc_fresnel_preintegrated(c, bbar), 1.0);
  matc_results[8u * i + 2u] = vec4(matc_fresnel(from_ior, reflectivity_mu.w), 1.0);
  matc_results[8u * i + 3u] = vec4(matc_fresnel(baked, reflectivity_mu.w), 1.0);
  // Per pixel from F0 = r, on rows at F0 = 0 of (0, 1, g - 0.5, k / 8 - 0.5).
  MatcFresnelCoefficients from_f0 = matc_coefficients_from_f0(
      matc_coefficients_from_baked(vec3(0.0), g - 0.5, k.xyz * 0.125 - 0.5), r);
  matc_results[8u * i + 4u] = vec4(matc_fresnel(from_f0, reflectivity_mu.w), 1.0);
  MatcFresnelCoefficients left = matc_check_f0_entries(r, 0, g, n_roughness.xyz, k.xyz);
  MatcFresnelCoefficients right = matc_check_f0_entries(r, 1, g, n_roughness.xyz, k.xyz);
  MatcFresnelCoefficients in_air = matc_coefficients_from_f0_entries(r, left, right);
  MatcFresnelCoefficients under_coat = matc_under_coat_from_f0_entries(r, left, right);
  matc_results[8u * i + 5u] = vec4(matc_fresnel(in_air, reflectivity_mu.w), 1.0);
  matc_results[8u * i + 6u] = vec4(matc_fresnel(under_coat, reflectivity_mu.w), 1.0);
  // glTF's metal-rough mix: the (r, g) metal with a dielectric of F0 g * 0.08 and F90 NdotV, by
  // metalness = roughness.
  vec3 dielectric = matc_dielectric_fresnel(g * 0.08, vec3(edge_tint_ndotv.w), reflectivity_mu.w);
  matc_results[8u * i + 7u] = vec4(
      matc_metal_rough(dielectric, matc_fresnel(c, reflectivity_mu.w), n_roughness.w), 1.0);
}
