fn matc_ltc_following{{suffix}}(c: MatcFresnelCoefficients, bbar: vec4f, ltc: vec4f, NdotV: f32,
                      roughness: f32, polygon: MatcLtcPolygon) -> vec3f {
  let geometry = matc_ltc_following_geometry(polygon, ltc, NdotV, roughness, bbar.x);
  return matc_ltc_following_radiance(geometry, bbar, matc_fresnel{{suffix}}(c, geometry.y),
                                     matc_fresnel_preintegrated(c, bbar));
}
