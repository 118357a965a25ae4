// matc {{version}}: material {{name}} from {{source_file}}. Generated (inputs {{inputs_hash}});
// do not edit, rerun matc. Needs matc_fresnel.wgsl in the same shader module.

// Fails to compile ("const assertion failed") when matc_fresnel.wgsl comes from another matc
// version than this file (matc {{version}}): regenerate both with one matc. Without the library,
// MATC_VERSION is an unresolved identifier here.
const_assert MATC_VERSION == {{version_number}};

// A metal under a thin film (index {{film_ior}}, {{film_thickness}} nm, coverage {{film_weight}}): F and Fbar
// come from its own table, {{name}}.film.<ext> (docs/thin-film.md), which holds the film's
// interference.
// F0 = ({{f0}}) in {{color_space}}; largest |F - exact Fresnel| over 2001 cosines: {{max_error}}.
// The 4-term fit, for F0 (matc_energy_compensation) only: it misses the film by {{fit_max_error}}.
const matc_coefficients_{{name}} = MatcFresnelCoefficients(
    vec4f({{red}}),
    vec4f({{green}}),
    vec4f({{blue}}));
{{film_stack}}
// F for a direct light: the film table's texel at matc_film_fresnel_texcoord(mu) (mu = dot(V, H);
// matc_film_fresnel fetches it).
fn matc_fresnel_{{name}}(film_texel: vec4f) -> vec3f {
  return film_texel.rgb;
}

// Preintegrated F: the film table's texel at matc_film_preintegrated_texcoord(NdotV, roughness)
// (matc_film_preintegrated fetches it), the roughness as matc_lut_texcoord takes it.
fn matc_fresnel_preintegrated_{{name}}(film_texel: vec4f) -> vec3f {
  return film_texel.rgb;
}

// Area lights of radiance 1 (docs/thin-film.md): the LTC integral times the film's preintegrated
// F; film_texel the film table's texel at matc_film_preintegrated_texcoord(NdotV, roughness)
// (matc_film_preintegrated), ltc from matc_ltc at (NdotV, roughness). A quad light ...
fn matc_ltc_quad_light_{{name}}(film_texel: vec4f, ltc: vec4f, N: vec3f, V: vec3f, P: vec3f,
                                q0: vec3f, q1: vec3f, q2: vec3f, q3: vec3f) -> vec3f {
  return matc_ltc_quad_integral(matc_ltc_transform(N, V, ltc), P, q0, q1, q2, q3) *
         matc_fresnel_preintegrated_{{name}}(film_texel);
}

// ... a disk light ...
fn matc_ltc_disk_light_{{name}}(film_texel: vec4f, ltc: vec4f, N: vec3f, V: vec3f, P: vec3f,
                                centre: vec3f, normal: vec3f, radius: f32) -> vec3f {
  return matc_ltc_disk_integral(matc_ltc_transform(N, V, ltc), P, centre, normal, radius) *
         matc_fresnel_preintegrated_{{name}}(film_texel);
}

// ... and a sphere light.
fn matc_ltc_sphere_light_{{name}}(film_texel: vec4f, ltc: vec4f, N: vec3f, V: vec3f, P: vec3f,
                                  centre: vec3f, radius: f32) -> vec3f {
  return matc_ltc_sphere_integral(matc_ltc_transform(N, V, ltc), P, centre, radius) *
         matc_fresnel_preintegrated_{{name}}(film_texel);
}
{{layer_texcoord}}