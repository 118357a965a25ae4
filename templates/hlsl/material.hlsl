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

// F0 = ({{f0}}) in {{color_space}}; largest |F - exact Fresnel| over 2001 cosines: {{max_error}}.
static const MatcFresnelCoefficients matc_coefficients_{{name}} = {
    float4({{red}}),
    float4({{green}}),
    float4({{blue}})};

// F for a direct light: mu = dot(V, H). {{clamp_note}}
float3 matc_fresnel_{{name}}(float mu) {
  return {{fresnel}}(matc_coefficients_{{name}}, mu);
}

// Preintegrated F from the table's texel at matc_lut_texcoord(NdotV, roughness).
float3 matc_fresnel_preintegrated_{{name}}(float4 bbar) {
  return {{fresnel_preintegrated}}(matc_coefficients_{{name}}, bbar);
}
{{layer_texcoord}}#endif  // MATC_MATERIAL_{{name}}
