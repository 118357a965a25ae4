#version 450
// matc {{version}}: the compute kernel that checks material {{name}} on a Vulkan device against the
// CPU runtime. For each query (mu, NdotV, roughness, -) it writes F(mu), the preintegrated F
// through the bound table and sampler, the same from the embedded table (zero without one) and
// from the closed form (matc_preintegrated_basis_analytic).
{{library}}
{{material}}
layout(local_size_x = 64) in;
layout(std430, set = 0, binding = 0) readonly buffer MatcQueries { vec4 matc_queries[]; };
layout(std430, set = 0, binding = 1) writeonly buffer MatcResults { vec4 matc_results[]; };
layout(set = 0, binding = 2) uniform texture2D matc_lut;
layout(set = 0, binding = 3) uniform sampler matc_lut_sampler;

void main() {
  uint i = gl_GlobalInvocationID.x;
  vec4 query = matc_queries[i];
  vec4 bbar = textureLod(sampler2D(matc_lut, matc_lut_sampler),
                         matc_lut_texcoord{{suffix}}(query.y, query.z), 0.0);
  vec4 embedded = vec4(0.0);
#ifdef MATC_EMBEDDED_LUT_SIZE
  embedded = vec4(matc_fresnel_preintegrated_{{name}}(
                      matc_preintegrated_basis_embedded{{suffix}}(query.y, query.z)), 1.0);
#endif
  matc_results[4u * i] = vec4(matc_fresnel_{{name}}(query.x), 1.0);
  matc_results[4u * i + 1u] = vec4(matc_fresnel_preintegrated_{{name}}(bbar), 1.0);
  matc_results[4u * i + 2u] = embedded;
  matc_results[4u * i + 3u] = vec4(matc_fresnel_preintegrated_{{name}}(
                                       matc_preintegrated_basis_analytic{{suffix}}(query.y, query.z)), 1.0);
}
