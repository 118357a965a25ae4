// matc {{version}}: material {{name}} from {{source_file}}. Generated (inputs {{inputs_hash}});
// do not edit, rerun matc. Include matc_fresnel.hlsl first.
#ifndef MATC_MATERIAL_{{name}}
#define MATC_MATERIAL_{{name}}
#ifndef MATC_FRESNEL_HLSL
#error matc: include matc_fresnel.hlsl before {{name}}.hlsl
#endif
#if MATC_VERSION != {{version_number}}
#error matc: {{name}}.hlsl comes from matc {{version}} but matc_fresnel.hlsl from another version; regenerate both with one matc
#endif

// A metal under a thin film (index {{film_ior}}, {{film_thickness}} nm, coverage {{film_weight}}): F and Fbar
// come from its own table, {{name}}.film.<ext> (docs/thin-film.md), which holds the film's
// interference.
// F0 = ({{f0}}) in {{color_space}}; largest |F - exact Fresnel| over 2001 cosines: {{max_error}}.
// The 4-term fit, for F0 (matc_energy_compensation) only: it misses the film by {{fit_max_error}}.
static const MatcFresnelCoefficients matc_coefficients_{{name}} = {
    float4({{red}}),
    float4({{green}}),
    float4({{blue}})};
{{film_stack}}
// F for a direct light: the film table's texel at matc_film_fresnel_texcoord(mu) (mu = dot(V, H);
// matc_film_fresnel fetches it).
float3 matc_fresnel_{{name}}(float4 film_texel) {
  return film_texel.rgb;
}

// Preintegrated F: the film table's texel at matc_film_preintegrated_texcoord(NdotV, roughness)
// (matc_film_preintegrated fetches it), the roughness as matc_lut_texcoord takes it.
float3 matc_fresnel_preintegrated_{{name}}(float4 film_texel) {
  return film_texel.rgb;
}

#ifdef MATC_LTC_SIZE
// Area lights of radiance 1 (docs/thin-film.md): the LTC integral times the film's preintegrated
// F; film_texel the film table's texel at matc_film_preintegrated_texcoord(NdotV, roughness)
// (matc_film_preintegrated), ltc from matc_ltc at (NdotV, roughness). A quad light ...
float3 matc_ltc_quad_light_{{name}}(float4 film_texel, float4 ltc, float3 N, float3 V, float3 P,
                                    float3 q0, float3 q1, float3 q2, float3 q3) {
  return matc_ltc_quad_integral(matc_ltc_transform(N, V, ltc), P, q0, q1, q2, q3) *
         matc_fresnel_preintegrated_{{name}}(film_texel);
}

// ... a disk light ...
float3 matc_ltc_disk_light_{{name}}(float4 film_texel, float4 ltc, float3 N, float3 V, float3 P,
                                    float3 centre, float3 normal, float radius) {
  return matc_ltc_disk_integral(matc_ltc_transform(N, V, ltc), P, centre, normal, radius) *
         matc_fresnel_preintegrated_{{name}}(film_texel);
}

// ... and a sphere light.
float3 matc_ltc_sphere_light_{{name}}(float4 film_texel, float4 ltc, float3 N, float3 V,
                                      float3 P, float3 centre, float radius) {
  return matc_ltc_sphere_integral(matc_ltc_transform(N, V, ltc), P, centre, radius) *
         matc_fresnel_preintegrated_{{name}}(film_texel);
}
#endif
{{layer_texcoord}}#endif  // MATC_MATERIAL_{{name}}
