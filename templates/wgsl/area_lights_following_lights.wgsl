// The quality level (the lobe's shape and the Fresnel follow the light across the lobe), with
// the roughness the table texels were read at: a quad light ...
fn matc_ltc_quad_light_following{{suffix}}(c: MatcFresnelCoefficients, bbar: vec4f, ltc: vec4f,
                                 roughness: f32, N: vec3f, V: vec3f, P: vec3f, q0: vec3f,
                                 q1: vec3f, q2: vec3f, q3: vec3f) -> vec3f {
  return matc_ltc_following{{suffix}}(
      c, bbar, ltc, dot(N, V), roughness,
      matc_ltc_quad_polygon(matc_ltc_transform(N, V, ltc), P, q0, q1, q2, q3));
}

// ... a disk light ...
fn matc_ltc_disk_light_following{{suffix}}(c: MatcFresnelCoefficients, bbar: vec4f, ltc: vec4f,
                                 roughness: f32, N: vec3f, V: vec3f, P: vec3f, centre: vec3f,
                                 normal: vec3f, radius: f32) -> vec3f {
  return matc_ltc_following{{suffix}}(
      c, bbar, ltc, dot(N, V), roughness,
      matc_ltc_disk_polygon(matc_ltc_transform(N, V, ltc), P, centre, normal, radius));
}

// ... and a sphere light.
fn matc_ltc_sphere_light_following{{suffix}}(c: MatcFresnelCoefficients, bbar: vec4f, ltc: vec4f,
                                   roughness: f32, N: vec3f, V: vec3f, P: vec3f, centre: vec3f,
                                   radius: f32) -> vec3f {
  return matc_ltc_following{{suffix}}(
      c, bbar, ltc, dot(N, V), roughness,
      matc_ltc_sphere_polygon(matc_ltc_transform(N, V, ltc), P, centre, radius));
}
