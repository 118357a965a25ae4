// matc {{version}}: material {{name}} from {{source_file}}. Generated (inputs {{inputs_hash}});
// do not edit, rerun matc. Include matc_fresnel.glsl first.
#ifndef MATC_MATERIAL_{{name}}
#define MATC_MATERIAL_{{name}}
#ifndef MATC_FRESNEL_GLSL
#error matc: include matc_fresnel.glsl before {{name}}.glsl
#endif
#if MATC_VERSION != {{version_number}}
#error matc: {{name}}.glsl comes from matc {{version}} but matc_fresnel.glsl from another version; regenerate both with one matc
#endif

// A metal under a thin film (index {{film_ior}}, {{film_thickness}} nm, coverage {{film_weight}}): F and Fbar
// come from its own table, {{name}}.film.<ext> (docs/thin-film.md), which holds the film's
// interference.
// F0 = ({{f0}}) in {{color_space}}; largest |F - exact Fresnel| over 2001 cosines: {{max_error}}.
// The 4-term fit, for F0 (matc_energy_compensation) only: it misses the film by {{fit_max_error}}.
const MatcFresnelCoefficients matc_coefficients_{{name}} = MatcFresnelCoefficients(
    vec4({{red}}),
    vec4({{green}}),
    vec4({{blue}}));
{{film_stack}}
// F for a direct light: the film table's texel at matc_film_fresnel_texcoord(mu) (mu = dot(V, H);
// MATC_FILM_FRESNEL fetches it).
vec3 matc_fresnel_{{name}}(vec4 film_texel) {
  return film_texel.rgb;
}

// Preintegrated F: the film table's texel at matc_film_preintegrated_texcoord(NdotV, roughness)
// (MATC_FILM_PREINTEGRATED fetches it), the roughness as matc_lut_texcoord takes it.
vec3 matc_fresnel_preintegrated_{{name}}(vec4 film_texel) {
  return film_texel.rgb;
}

#ifdef MATC_LTC_SIZE
// Area lights of radiance 1 (docs/thin-film.md): the LTC integral times the film's preintegrated
// F; film_texel the film table's texel at matc_film_preintegrated_texcoord(NdotV, roughness)
// (MATC_FILM_PREINTEGRATED), ltc from matc_ltc at (NdotV, roughness). A quad light ...
vec3 matc_ltc_quad_light_{{name}}(vec4 film_texel, vec4 ltc, vec3 N, vec3 V, vec3 P, vec3 q0,
                                  vec3 q1, vec3 q2, vec3 q3) {
  return matc_ltc_quad_integral(matc_ltc_transform(N, V, ltc), P, q0, q1, q2, q3) *
         matc_fresnel_preintegrated_{{name}}(film_texel);
}

// ... a disk light ...
vec3 matc_ltc_disk_light_{{name}}(vec4 film_texel, vec4 ltc, vec3 N, vec3 V, vec3 P, vec3 centre,
                                  vec3 normal, float radius) {
  return matc_ltc_disk_integral(matc_ltc_transform(N, V, ltc), P, centre, normal, radius) *
         matc_fresnel_preintegrated_{{name}}(film_texel);
}

// ... and a sphere light.
vec3 matc_ltc_sphere_light_{{name}}(vec4 film_texel, vec4 ltc, vec3 N, vec3 V, vec3 P,
                                    vec3 centre, float radius) {
  return matc_ltc_sphere_integral(matc_ltc_transform(N, V, ltc), P, centre, radius) *
         matc_fresnel_preintegrated_{{name}}(film_texel);
}
#endif
{{layer_texcoord}}#endif  // MATC_MATERIAL_{{name}}
