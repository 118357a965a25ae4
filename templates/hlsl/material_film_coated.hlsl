// matc {{version}}: material {{name}} from {{source_file}}, a metal under a thin film under a coat
// (docs/thin-film.md). Generated (inputs {{inputs_hash}}); do not edit, rerun matc. Include
// matc_fresnel.hlsl first.
#ifndef MATC_MATERIAL_{{name}}
#define MATC_MATERIAL_{{name}}
#ifndef MATC_FRESNEL_HLSL
#error matc: include matc_fresnel.hlsl before {{name}}.hlsl
#endif
#if MATC_VERSION != {{version_number}}
#error matc: {{name}}.hlsl comes from matc {{version}} but matc_fresnel.hlsl from another version; regenerate both with one matc
#endif

// Two lobes: the coat's (matc_coat_fresnel_{{name}}, sampled at the coat's roughness) and the
// base's, a thin film (index {{film_ior}}, {{film_thickness}} nm, coverage {{film_weight}}) over the metal seen
// through the coat, whose F and Fbar come from its own table, {{name}}.film.<ext>, the coat's
// transmission and tint included (matc_fresnel_{{name}}, at the metal's roughness). The base lobe
// against the exact layered base over 2001 cosines: largest |F - exact| {{max_error}}; both lobes
// against the exact layered reflectance (smooth interfaces): {{layered_max_error}}.
// The metal in air: F0 = ({{f0}}) in {{color_space}}; the 4-term fit, for F0
// (matc_energy_compensation) only: it misses the film by {{fit_max_error}}.
static const MatcFresnelCoefficients matc_coefficients_{{name}} = {
    float4({{red}}),
    float4({{green}}),
    float4({{blue}})};
// The 4-term fit of the filmed metal seen through the coat, for the base lobe's F0 under the coat
// (matc_energy_compensation) only.
static const MatcFresnelCoefficients matc_under_coat_coefficients_{{name}} = {
    float4({{under_red}}),
    float4({{under_green}}),
    float4({{under_blue}})};
{{coat_lobe_constants}}

// The base lobe's F for a direct light: the film table's texel at matc_film_fresnel_texcoord(mu)
// (mu = dot(V, H); matc_film_fresnel fetches it).
float3 matc_fresnel_{{name}}(float4 film_texel) {
  return film_texel.rgb;
}

{{coat_lobe_functions}}

// The base lobe's preintegrated F: the film table's texel at
// matc_film_preintegrated_texcoord(NdotV, roughness) (matc_film_preintegrated fetches it), the
// roughness as matc_lut_texcoord takes it.
float3 matc_fresnel_preintegrated_{{name}}(float4 film_texel) {
  return film_texel.rgb;
}

{{coat_lobe_preintegrated}}

#ifdef MATC_LTC_SIZE
// Area lights of radiance 1 on both lobes: each lobe's LTC integral times its preintegrated F;
// film_texel the film table's texel at matc_film_preintegrated_texcoord(NdotV, roughness) and ltc
// from matc_ltc at (NdotV, roughness), coat_bbar and coat_ltc at (NdotV,
// matc_coat_roughness_{{name}}). A quad light ...
float3 matc_ltc_quad_light_{{name}}(float4 film_texel, float4 coat_bbar, float4 ltc, float4 coat_ltc, float3 N,
                                  float3 V, float3 P, float3 q0, float3 q1, float3 q2, float3 q3) {
  return matc_ltc_quad_integral(matc_ltc_transform(N, V, ltc), P, q0, q1, q2, q3) *
             matc_fresnel_preintegrated_{{name}}(film_texel) +
         matc_ltc_quad_integral(matc_ltc_transform(N, V, coat_ltc), P, q0, q1, q2, q3) *
             matc_coat_fresnel_preintegrated_{{name}}(coat_bbar);
}

// ... a disk light ...
float3 matc_ltc_disk_light_{{name}}(float4 film_texel, float4 coat_bbar, float4 ltc, float4 coat_ltc, float3 N,
                                  float3 V, float3 P, float3 centre, float3 normal, float radius) {
  return matc_ltc_disk_integral(matc_ltc_transform(N, V, ltc), P, centre, normal, radius) *
             matc_fresnel_preintegrated_{{name}}(film_texel) +
         matc_ltc_disk_integral(matc_ltc_transform(N, V, coat_ltc), P, centre, normal, radius) *
             matc_coat_fresnel_preintegrated_{{name}}(coat_bbar);
}

// ... and a sphere light.
float3 matc_ltc_sphere_light_{{name}}(float4 film_texel, float4 coat_bbar, float4 ltc, float4 coat_ltc,
                                    float3 N, float3 V, float3 P, float3 centre, float radius) {
  return matc_ltc_sphere_integral(matc_ltc_transform(N, V, ltc), P, centre, radius) *
             matc_fresnel_preintegrated_{{name}}(film_texel) +
         matc_ltc_sphere_integral(matc_ltc_transform(N, V, coat_ltc), P, centre, radius) *
             matc_coat_fresnel_preintegrated_{{name}}(coat_bbar);
}
#endif
{{layer_texcoord}}#endif  // MATC_MATERIAL_{{name}}
