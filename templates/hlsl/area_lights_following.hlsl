float3 matc_ltc_following{{suffix}}(MatcFresnelCoefficients c, float4 bbar, float4 ltc, float NdotV,
                          float roughness, MatcLtcPolygon polygon) {
  float3 geometry = matc_ltc_following_geometry(polygon, ltc, NdotV, roughness, bbar.x);
  return matc_ltc_following_radiance(geometry, bbar, matc_fresnel{{suffix}}(c, geometry.y),
                                     matc_fresnel_preintegrated(c, bbar));
}
