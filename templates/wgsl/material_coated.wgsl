// matc {{version}}: material {{name}} from {{source_file}}, a metal under a coat (docs/coating.md).
// Generated (inputs {{inputs_hash}}); do not edit, rerun matc. Needs matc_fresnel.wgsl in the
// same shader module.

// Fails to compile ("const assertion failed") when matc_fresnel.wgsl comes from another matc
// version than this file (matc {{version}}): regenerate both with one matc. Without the library,
// MATC_VERSION is an unresolved identifier here.
const_assert MATC_VERSION == {{version_number}};

// Two lobes: the coat's (matc_coat_fresnel_{{name}}, sampled at the coat's roughness) and the
// base's (matc_fresnel_{{name}}, at the metal's). Together, against the exact layered
// reflectance (smooth interfaces) over 2001 cosines: largest |F - exact| {{layered_max_error}}.
// The metal in air: F0 = ({{f0}}) in {{color_space}}.
const matc_coefficients_{{name}} = MatcFresnelCoefficients(
    vec4f({{red}}),
    vec4f({{green}}),
    vec4f({{blue}}));
// The metal seen through the coat: its curve at the metal/coat interface, at the cosines inside
// the coat; largest |F - exact|: {{under_coat_max_error}}.
const matc_under_coat_coefficients_{{name}} = MatcFresnelCoefficients(
    vec4f({{under_red}}),
    vec4f({{under_green}}),
    vec4f({{under_blue}}));
{{coat_lobe_constants}}

// The coat's tint over the round trip at cosine mu in air, color^(1 / mu_inside) (Beer's law;
// 1 for a clear coat).
fn matc_coat_tint_{{name}}(mu: f32) -> vec3f {
{{tint_body}}
}

// The base under the coat: in through the coat, reflected by the metal and the coat's underside
// any number of times, out again: mix(in air, (1 - f)^2 v / (1 - f min(v, 1)), weight), or
// the second term alone under a full coat.
fn matc_coated_base_{{name}}(in_air: MatcFresnelCoefficients, under_coat: MatcFresnelCoefficients,
                             values: vec4f, coat_values: vec4f,
                             tint: vec3f) -> vec3f {
  let f = clamp(dot(matc_coat_coefficients_{{name}}, coat_values), 0.0, 1.0);
  let v = matc_combine(under_coat, values) * tint;
  // One reciprocal for the three channels' sums of bounces: 1 / d_c = (the other two) / (d_r d_g d_b).
  let d = max(1.0 - f * min(v, vec3f(1.0)), vec3f(1e-6));
  let scale = (1.0 - f) * (1.0 - f) / (d.x * d.y * d.z);
  let through = v * scale * vec3f(d.y * d.z, d.x * d.z, d.x * d.y);
  return {{base}};
}

// A textured metal under this coat (docs/gltf.md): the base lobe with this pixel's coefficients
// in air and under the coat, in_air and under_coat (MATC_COEFFICIENTS_FROM_F0_TABLE and
// MATC_UNDER_COAT_FROM_F0_TABLE of the metal's F0 table), in place of matc_coefficients_{{name}}
// and matc_under_coat_coefficients_{{name}}; the coat and its layering are this material's.
fn matc_fresnel_textured_{{name}}(in_air: MatcFresnelCoefficients, under_coat: MatcFresnelCoefficients,
                                  mu: f32) -> vec3f {
  let b = matc_basis(mu);
  return matc_coated_base_{{name}}(in_air, under_coat, b, b, matc_coat_tint_{{name}}(mu));
}
fn matc_fresnel_preintegrated_textured_{{name}}(in_air: MatcFresnelCoefficients,
                                                 under_coat: MatcFresnelCoefficients, bbar: vec4f,
                                                 coat_bbar: vec4f, NdotV: f32) -> vec3f {
  return matc_coated_base_{{name}}(in_air, under_coat, bbar, coat_bbar, matc_coat_tint_{{name}}(NdotV));
}

// The base lobe's F for a direct light: mu = dot(V, H).
fn matc_fresnel_{{name}}(mu: f32) -> vec3f {
  return matc_fresnel_textured_{{name}}(matc_coefficients_{{name}}, matc_under_coat_coefficients_{{name}},
                                       mu);
}

{{coat_lobe_functions}}

// The base lobe's preintegrated F: bbar from the table at matc_lut_texcoord(NdotV, roughness),
// coat_bbar at matc_lut_texcoord(NdotV, matc_coat_roughness_{{name}}).
fn matc_fresnel_preintegrated_{{name}}(bbar: vec4f, coat_bbar: vec4f, NdotV: f32) -> vec3f {
  return matc_fresnel_preintegrated_textured_{{name}}(
      matc_coefficients_{{name}}, matc_under_coat_coefficients_{{name}}, bbar, coat_bbar, NdotV);
}

{{coat_lobe_preintegrated}}

// Area lights of radiance 1 on both lobes (docs/coating.md): each lobe's LTC integral times its
// preintegrated F; ltc and bbar at (NdotV, roughness) from matc_ltc and matc_lut, coat_ltc and
// coat_bbar at (NdotV, matc_coat_roughness_{{name}}). A quad light ...
fn matc_ltc_quad_light_{{name}}(bbar: vec4f, coat_bbar: vec4f, ltc: vec4f, coat_ltc: vec4f,
                                N: vec3f, V: vec3f, P: vec3f, q0: vec3f, q1: vec3f, q2: vec3f,
                                q3: vec3f) -> vec3f {
  let NdotV = clamp(dot(N, V), 0.0, 1.0);
  return matc_ltc_quad_integral(matc_ltc_transform(N, V, ltc), P, q0, q1, q2, q3) *
             matc_fresnel_preintegrated_{{name}}(bbar, coat_bbar, NdotV) +
         matc_ltc_quad_integral(matc_ltc_transform(N, V, coat_ltc), P, q0, q1, q2, q3) *
             matc_coat_fresnel_preintegrated_{{name}}(coat_bbar);
}

// ... a disk light ...
fn matc_ltc_disk_light_{{name}}(bbar: vec4f, coat_bbar: vec4f, ltc: vec4f, coat_ltc: vec4f,
                                N: vec3f, V: vec3f, P: vec3f, centre: vec3f, normal: vec3f,
                                radius: f32) -> vec3f {
  let NdotV = clamp(dot(N, V), 0.0, 1.0);
  return matc_ltc_disk_integral(matc_ltc_transform(N, V, ltc), P, centre, normal, radius) *
             matc_fresnel_preintegrated_{{name}}(bbar, coat_bbar, NdotV) +
         matc_ltc_disk_integral(matc_ltc_transform(N, V, coat_ltc), P, centre, normal, radius) *
             matc_coat_fresnel_preintegrated_{{name}}(coat_bbar);
}

// ... and a sphere light.
fn matc_ltc_sphere_light_{{name}}(bbar: vec4f, coat_bbar: vec4f, ltc: vec4f, coat_ltc: vec4f,
                                  N: vec3f, V: vec3f, P: vec3f, centre: vec3f,
                                  radius: f32) -> vec3f {
  let NdotV = clamp(dot(N, V), 0.0, 1.0);
  return matc_ltc_sphere_integral(matc_ltc_transform(N, V, ltc), P, centre, radius) *
             matc_fresnel_preintegrated_{{name}}(bbar, coat_bbar, NdotV) +
         matc_ltc_sphere_integral(matc_ltc_transform(N, V, coat_ltc), P, centre, radius) *
             matc_coat_fresnel_preintegrated_{{name}}(coat_bbar);
}
