// matc {{version}}: material {{name}} from {{source_file}}, a metal under a thin film under a coat
// (docs/thin-film.md). Generated (inputs {{inputs_hash}}); do not edit, rerun matc. Needs
// matc_fresnel.wgsl in the same shader module.

// Fails to compile ("const assertion failed") when matc_fresnel.wgsl comes from another matc
// version than this file (matc {{version}}): regenerate both with one matc. Without the library,
// MATC_VERSION is an unresolved identifier here.
const_assert MATC_VERSION == {{version_number}};

// Two lobes: the coat's (matc_coat_fresnel_{{name}}, sampled at the coat's roughness) and the
// base's, a thin film (index {{film_ior}}, {{film_thickness}} nm, coverage {{film_weight}}) over the metal seen
// through the coat, whose F and Fbar come from its own table, {{name}}.film.<ext>, the coat's
// transmission and tint included (matc_fresnel_{{name}}, at the metal's roughness). The base lobe
// against the exact layered base over 2001 cosines: largest |F - exact| {{max_error}}; both lobes
// against the exact layered reflectance (smooth interfaces): {{layered_max_error}}.
// The metal in air: F0 = ({{f0}}) in {{color_space}}; the 4-term fit, for F0
// (matc_energy_compensation) only: it misses the film by {{fit_max_error}}.
const matc_coefficients_{{name}} = MatcFresnelCoefficients(
    vec4f({{red}}),
    vec4f({{green}}),
    vec4f({{blue}}));
// The 4-term fit of the filmed metal seen through the coat, for the base lobe's F0 under the coat
// (matc_energy_compensation) only.
const matc_under_coat_coefficients_{{name}} = MatcFresnelCoefficients(
    vec4f({{under_red}}),
    vec4f({{under_green}}),
    vec4f({{under_blue}}));
{{coat_lobe_constants}}

// The base lobe's F for a direct light: the film table's texel at matc_film_fresnel_texcoord(mu)
// (mu = dot(V, H); matc_film_fresnel fetches it).
fn matc_fresnel_{{name}}(film_texel: vec4f) -> vec3f {
  return film_texel.rgb;
}

{{coat_lobe_functions}}

// The base lobe's preintegrated F: the film table's texel at
// matc_film_preintegrated_texcoord(NdotV, roughness) (matc_film_preintegrated fetches it), the
// roughness as matc_lut_texcoord takes it.
fn matc_fresnel_preintegrated_{{name}}(film_texel: vec4f) -> vec3f {
  return film_texel.rgb;
}

{{coat_lobe_preintegrated}}

// Area lights of radiance 1 on both lobes: each lobe's LTC integral times its preintegrated F;
// film_texel the film table's texel at matc_film_preintegrated_texcoord(NdotV, roughness) and ltc
// from matc_ltc at (NdotV, roughness), coat_bbar and coat_ltc at (NdotV,
// matc_coat_roughness_{{name}}). A quad light ...
fn matc_ltc_quad_light_{{name}}(film_texel: vec4f, coat_bbar: vec4f, ltc: vec4f, coat_ltc: vec4f,
                                N: vec3f, V: vec3f, P: vec3f, q0: vec3f, q1: vec3f, q2: vec3f,
                                q3: vec3f) -> vec3f {
  return matc_ltc_quad_integral(matc_ltc_transform(N, V, ltc), P, q0, q1, q2, q3) *
             matc_fresnel_preintegrated_{{name}}(film_texel) +
         matc_ltc_quad_integral(matc_ltc_transform(N, V, coat_ltc), P, q0, q1, q2, q3) *
             matc_coat_fresnel_preintegrated_{{name}}(coat_bbar);
}

// ... a disk light ...
fn matc_ltc_disk_light_{{name}}(film_texel: vec4f, coat_bbar: vec4f, ltc: vec4f, coat_ltc: vec4f,
                                N: vec3f, V: vec3f, P: vec3f, centre: vec3f, normal: vec3f,
                                radius: f32) -> vec3f {
  return matc_ltc_disk_integral(matc_ltc_transform(N, V, ltc), P, centre, normal, radius) *
             matc_fresnel_preintegrated_{{name}}(film_texel) +
         matc_ltc_disk_integral(matc_ltc_transform(N, V, coat_ltc), P, centre, normal, radius) *
             matc_coat_fresnel_preintegrated_{{name}}(coat_bbar);
}

// ... and a sphere light.
fn matc_ltc_sphere_light_{{name}}(film_texel: vec4f, coat_bbar: vec4f, ltc: vec4f,
                                  coat_ltc: vec4f, N: vec3f, V: vec3f, P: vec3f, centre: vec3f,
                                  radius: f32) -> vec3f {
  return matc_ltc_sphere_integral(matc_ltc_transform(N, V, ltc), P, centre, radius) *
             matc_fresnel_preintegrated_{{name}}(film_texel) +
         matc_ltc_sphere_integral(matc_ltc_transform(N, V, coat_ltc), P, centre, radius) *
             matc_coat_fresnel_preintegrated_{{name}}(coat_bbar);
}
{{layer_texcoord}}