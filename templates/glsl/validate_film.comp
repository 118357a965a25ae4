#version 450
// matc {{version}}: the compute kernel that checks filmed material {{name}} on a Vulkan device
// against the CPU runtime. For each query (mu, NdotV, roughness, thickness) it writes F(mu) and
// the preintegrated F at (NdotV, roughness), both from the film's table (binding 6) through the
// table sampler (a thickness per pixel: at the thickness coordinate), then a quad light of
// radiance 1 overhead (the shading frame: normal +z, view in the xz-plane at NdotV) through
// matc_ltc.
{{library}}
{{material}}
layout(local_size_x = 64) in;
layout(std430, set = 0, binding = 0) readonly buffer MatcQueries { vec4 matc_queries[]; };
layout(std430, set = 0, binding = 1) writeonly buffer MatcResults { vec4 matc_results[]; };
layout(set = 0, binding = 3) uniform sampler matc_lut_sampler;
layout(set = 0, binding = 5) uniform texture2D matc_ltc;
layout(set = 0, binding = 6) uniform texture2D matc_film;

void main() {
  uint i = gl_GlobalInvocationID.x;
  vec4 query = matc_queries[i];
  vec4 direct = {{film_direct}};
  vec4 image = {{film_image}};
  vec3 V = vec3(sqrt(max(1.0 - query.y * query.y, 0.0)), 0.0, query.y);
  vec4 ltc = textureLod(sampler2D(matc_ltc, matc_lut_sampler),
                        matc_ltc_texcoord(query.y, query.z), 0.0);
  matc_results[3u * i] = vec4(matc_fresnel_{{name}}(direct), 1.0);
  matc_results[3u * i + 1u] = vec4(matc_fresnel_preintegrated_{{name}}(image), 1.0);
  matc_results[3u * i + 2u] = vec4(
      matc_ltc_quad_light_{{name}}(image, ltc, vec3(0.0, 0.0, 1.0), V, vec3(0.0), {{quad}}), 1.0);
}
