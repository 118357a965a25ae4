vec3 matc_ltc_following{{suffix}}(MatcFresnelCoefficients c, vec4 bbar, vec4 ltc, float NdotV,
                        float roughness, MatcLtcPolygon polygon) {
  vec3 geometry = matc_ltc_following_geometry(polygon, ltc, NdotV, roughness, bbar.x);
  return matc_ltc_following_radiance(geometry, bbar, matc_fresnel{{suffix}}(c, geometry.y),
                                     matc_fresnel_preintegrated(c, bbar));
}
