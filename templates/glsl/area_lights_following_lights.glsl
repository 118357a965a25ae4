// The quality level (the lobe's shape and the Fresnel follow the light across the lobe), with
// the roughness the table texels were read at: a quad light ...
vec3 matc_ltc_quad_light_following{{suffix}}(MatcFresnelCoefficients c, vec4 bbar, vec4 ltc, float roughness,
                                   vec3 N, vec3 V, vec3 P, vec3 q0, vec3 q1, vec3 q2, vec3 q3) {
  return matc_ltc_following{{suffix}}(
      c, bbar, ltc, dot(N, V), roughness,
      matc_ltc_quad_polygon(matc_ltc_transform(N, V, ltc), P, q0, q1, q2, q3));
}

// ... a disk light ...
vec3 matc_ltc_disk_light_following{{suffix}}(MatcFresnelCoefficients c, vec4 bbar, vec4 ltc, float roughness,
                                   vec3 N, vec3 V, vec3 P, vec3 centre, vec3 normal,
                                   float radius) {
  return matc_ltc_following{{suffix}}(
      c, bbar, ltc, dot(N, V), roughness,
      matc_ltc_disk_polygon(matc_ltc_transform(N, V, ltc), P, centre, normal, radius));
}

// ... and a sphere light.
vec3 matc_ltc_sphere_light_following{{suffix}}(MatcFresnelCoefficients c, vec4 bbar, vec4 ltc,
                                     float roughness, vec3 N, vec3 V, vec3 P, vec3 centre,
                                     float radius) {
  return matc_ltc_following{{suffix}}(
      c, bbar, ltc, dot(N, V), roughness,
      matc_ltc_sphere_polygon(matc_ltc_transform(N, V, ltc), P, centre, radius));
}
