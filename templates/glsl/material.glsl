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

// F0 = ({{f0}}) in {{color_space}}; largest |F - exact Fresnel| over 2001 cosines: {{max_error}}.
const MatcFresnelCoefficients matc_coefficients_{{name}} = MatcFresnelCoefficients(
    vec4({{red}}),
    vec4({{green}}),
    vec4({{blue}}));

// F for a direct light: mu = dot(V, H). {{clamp_note}}
vec3 matc_fresnel_{{name}}(float mu) {
  return {{fresnel}}(matc_coefficients_{{name}}, mu);
}

// Preintegrated F from the table's texel at matc_lut_texcoord(NdotV, roughness).
vec3 matc_fresnel_preintegrated_{{name}}(vec4 bbar) {
  return {{fresnel_preintegrated}}(matc_coefficients_{{name}}, bbar);
}
{{layer_texcoord}}#endif  // MATC_MATERIAL_{{name}}
