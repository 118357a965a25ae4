// The quality level (the lobe's shape and the Fresnel follow the light across the lobe), with
// the roughness the table texels were read at: a quad light ...
float3 matc_ltc_quad_light_following{{suffix}}(MatcFresnelCoefficients c, float4 bbar, float4 ltc,
                                     float roughness, float3 N, float3 V, float3 P, float3 q0,
                                     float3 q1, float3 q2, float3 q3) {
  return matc_ltc_following{{suffix}}(
      c, bbar, ltc, dot(N, V), roughness,
      matc_ltc_quad_polygon(matc_ltc_transform(N, V, ltc), P, q0, q1, q2, q3));
}

// ... a disk light ...
float3 matc_ltc_disk_light_following{{suffix}}(MatcFresnelCoefficients c, float4 bbar, float4 ltc,
                                     float roughness, float3 N, float3 V, float3 P,
                                     float3 centre, float3 normal, float radius) {
  return matc_ltc_following{{suffix}}(
      c, bbar, ltc, dot(N, V), roughness,
      matc_ltc_disk_polygon(matc_ltc_transform(N, V, ltc), P, centre, normal, radius));
}

// ... and a sphere light.
float3 matc_ltc_sphere_light_following{{suffix}}(MatcFresnelCoefficients c, float4 bbar, float4 ltc,
                                       float roughness, float3 N, float3 V, float3 P,
                                       float3 centre, float radius) {
  return matc_ltc_following{{suffix}}(
      c, bbar, ltc, dot(N, V), roughness,
      matc_ltc_sphere_polygon(matc_ltc_transform(N, V, ltc), P, centre, radius));
}
