#version 450
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
layout(local_size_x = 64) in;
layout(std430, set = 0, binding = 0) readonly buffer MatcQueries { vec4 matc_queries[]; };
layout(std430, set = 0, binding = 1) writeonly buffer MatcResults { vec4 matc_results[]; };
layout(set = 0, binding = 2) uniform texture2D matc_lut;
layout(set = 0, binding = 3) uniform sampler matc_lut_sampler;
layout(set = 0, binding = 5) uniform texture2D matc_ltc;
layout(set = 0, binding = 6) uniform texture2D matc_film;

void main() {
  uint i = gl_GlobalInvocationID.x;
  vec4 query = matc_queries[i];
  float coat_roughness = matc_coat_roughness_{{name}};
  vec4 direct = MATC_FILM_FRESNEL(sampler2D(matc_film, matc_lut_sampler), query.x);
  vec4 image = MATC_FILM_PREINTEGRATED(sampler2D(matc_film, matc_lut_sampler), query.y, query.z);
  vec4 coat_bbar = textureLod(sampler2D(matc_lut, matc_lut_sampler),
                              matc_lut_texcoord(query.y, coat_roughness), 0.0);
  vec3 V = vec3(sqrt(max(1.0 - query.y * query.y, 0.0)), 0.0, query.y);
  vec4 ltc = textureLod(sampler2D(matc_ltc, matc_lut_sampler),
                        matc_ltc_texcoord(query.y, query.z), 0.0);
  vec4 coat_ltc = textureLod(sampler2D(matc_ltc, matc_lut_sampler),
                             matc_ltc_texcoord(query.y, coat_roughness), 0.0);
  matc_results[4u * i] = vec4(matc_fresnel_{{name}}(direct), matc_coat_fresnel_{{name}}(query.x));
  matc_results[4u * i + 1u] = vec4(matc_fresnel_preintegrated_{{name}}(image),
                                   matc_coat_fresnel_preintegrated_{{name}}(coat_bbar));
  matc_results[4u * i + 2u] = vec4(
      matc_ltc_quad_light_{{name}}(image, coat_bbar, ltc, coat_ltc, vec3(0.0, 0.0, 1.0), V,
                                   vec3(0.0), {{quad}}),
      1.0);
  matc_results[4u * i + 3u] =
      vec4(matc_metal_rough_{{name}}(matc_dielectric_fresnel(vec3(0.04), vec3(1.0), query.x),
                                     matc_fresnel_{{name}}(direct), query.z, query.y),
           matc_coat_transmission_{{name}}(query.y));
}
