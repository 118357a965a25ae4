// matc {{version}}: material {{name}} from {{source_file}}. Generated (inputs {{inputs_hash}});
// do not edit, rerun matc. Needs matc_fresnel.wgsl in the same shader module.

// Fails to compile ("const assertion failed") when matc_fresnel.wgsl comes from another matc
// version than this file (matc {{version}}): regenerate both with one matc. Without the library,
// MATC_VERSION is an unresolved identifier here.
const_assert MATC_VERSION == {{version_number}};

// F0 = ({{f0}}) in {{color_space}}; largest |F - exact Fresnel| over 2001 cosines: {{max_error}}.
const matc_coefficients_{{name}} = MatcFresnelCoefficients(
    vec4f({{red}}),
    vec4f({{green}}),
    vec4f({{blue}}));

// F for a direct light: mu = dot(V, H). {{clamp_note}}
fn matc_fresnel_{{name}}(mu: f32) -> vec3f {
  return {{fresnel}}(matc_coefficients_{{name}}, mu);
}

// Preintegrated F from the table's texel at matc_lut_texcoord(NdotV, roughness).
fn matc_fresnel_preintegrated_{{name}}(bbar: vec4f) -> vec3f {
  return {{fresnel_preintegrated}}(matc_coefficients_{{name}}, bbar);
}
{{layer_texcoord}}