// matc {{version}}: material {{name}} from {{source_file}}, a metal under a coat (docs/coating.md).
// Generated (inputs {{inputs_hash}}); do not edit, rerun matc. Include matc_fresnel.hlsl first.
#ifndef MATC_MATERIAL_{{name}}
#define MATC_MATERIAL_{{name}}
#ifndef MATC_FRESNEL_HLSL
#error matc: include matc_fresnel.hlsl before {{name}}.hlsl
#endif
#if MATC_VERSION != {{version_number}}
#error matc: {{name}}.hlsl comes from matc {{version}} but matc_fresnel.hlsl from another version; regenerate both with one matc
#endif

// Two lobes: the coat's (matc_coat_fresnel_{{name}}, sampled at the coat's roughness) and the
// base's (matc_fresnel_{{name}}, at the metal's). Together, against the exact layered
// reflectance (smooth interfaces) over 2001 cosines: largest |F - exact| {{layered_max_error}}.
// The metal in air: F0 = ({{f0}}) in {{color_space}}.
static const MatcFresnelCoefficients matc_coefficients_{{name}} = {
    float4({{red}}),
    float4({{green}}),
    float4({{blue}})};
// The metal seen through the coat: its curve at the metal/coat interface, at the cosines inside
// the coat; largest |F - exact|: {{under_coat_max_error}}.
static const MatcFresnelCoefficients matc_under_coat_coefficients_{{name}} = {
    float4({{under_red}}),
    float4({{under_green}}),
    float4({{under_blue}})};
{{coat_lobe_constants}}

// The coat's tint over the round trip at cosine mu in air, color^(1 / mu_inside) (Beer's law;
// 1 for a clear coat).
float3 matc_coat_tint_{{name}}(float mu) {
{{tint_body}}
}

// The base under the coat: in through the coat, reflected by the metal and the coat's underside
// any number of times, out again: lerp(in air, (1 - f)^2 v / (1 - f min(v, 1)), weight), or
// the second term alone under a full coat.
float3 matc_coated_base_{{name}}(MatcFresnelCoefficients in_air, MatcFresnelCoefficients under_coat,
                                    float4 values, float4 coat_values,
                                    float3 tint) {
  float f = clamp(dot(matc_coat_coefficients_{{name}}, coat_values), 0.0, 1.0);
  float3 v = matc_combine(under_coat, values) * tint;
  // One reciprocal for the three channels' sums of bounces: 1 / d_c = (the other two) / (d_r d_g d_b).
  float3 d = max(1.0 - f * min(v, float3(1.0)), float3(1e-6));
  float scale = (1.0 - f) * (1.0 - f) / (d.x * d.y * d.z);
  float3 through = v * scale * float3(d.y * d.z, d.x * d.z, d.x * d.y);
  return {{base}};
}

// A textured metal under this coat (docs/gltf.md): the base lobe with this pixel's coefficients
// in air and under the coat, in_air and under_coat (MATC_COEFFICIENTS_FROM_F0_TABLE and
// MATC_UNDER_COAT_FROM_F0_TABLE of the metal's F0 table), in place of matc_coefficients_{{name}}
// and matc_under_coat_coefficients_{{name}}; the coat and its layering are this material's.
float3 matc_fresnel_textured_{{name}}(MatcFresnelCoefficients in_air, MatcFresnelCoefficients under_coat,
                                        float mu) {
  float4 b = matc_basis(mu);
  return matc_coated_base_{{name}}(in_air, under_coat, b, b, matc_coat_tint_{{name}}(mu));
}
float3 matc_fresnel_preintegrated_textured_{{name}}(MatcFresnelCoefficients in_air,
                                                       MatcFresnelCoefficients under_coat, float4 bbar,
                                                       float4 coat_bbar, float NdotV) {
  return matc_coated_base_{{name}}(in_air, under_coat, bbar, coat_bbar, matc_coat_tint_{{name}}(NdotV));
}

// The base lobe's F for a direct light: mu = dot(V, H).
float3 matc_fresnel_{{name}}(float mu) {
  return matc_fresnel_textured_{{name}}(matc_coefficients_{{name}}, matc_under_coat_coefficients_{{name}},
                                       mu);
}

{{coat_lobe_functions}}

// The base lobe's preintegrated F: bbar from the table at matc_lut_texcoord(NdotV, roughness),
// coat_bbar at matc_lut_texcoord(NdotV, matc_coat_roughness_{{name}}).
float3 matc_fresnel_preintegrated_{{name}}(float4 bbar, float4 coat_bbar, float NdotV) {
  return matc_fresnel_preintegrated_textured_{{name}}(
      matc_coefficients_{{name}}, matc_under_coat_coefficients_{{name}}, bbar, coat_bbar, NdotV);
}

{{coat_lobe_preintegrated}}

#ifdef MATC_LTC_SIZE
// Area lights of radiance 1 on both lobes (docs/coating.md): each lobe's LTC integral times its
// preintegrated F; ltc and bbar at (NdotV, roughness) from matc_ltc and matc_lut, coat_ltc and
// coat_bbar at (NdotV, matc_coat_roughness_{{name}}). A quad light ...
float3 matc_ltc_quad_light_{{name}}(float4 bbar, float4 coat_bbar, float4 ltc, float4 coat_ltc, float3 N,
                                  float3 V, float3 P, float3 q0, float3 q1, float3 q2, float3 q3) {
  float NdotV = clamp(dot(N, V), 0.0, 1.0);
  return matc_ltc_quad_integral(matc_ltc_transform(N, V, ltc), P, q0, q1, q2, q3) *
             matc_fresnel_preintegrated_{{name}}(bbar, coat_bbar, NdotV) +
         matc_ltc_quad_integral(matc_ltc_transform(N, V, coat_ltc), P, q0, q1, q2, q3) *
             matc_coat_fresnel_preintegrated_{{name}}(coat_bbar);
}

// ... a disk light ...
float3 matc_ltc_disk_light_{{name}}(float4 bbar, float4 coat_bbar, float4 ltc, float4 coat_ltc, float3 N,
                                  float3 V, float3 P, float3 centre, float3 normal, float radius) {
  float NdotV = clamp(dot(N, V), 0.0, 1.0);
  return matc_ltc_disk_integral(matc_ltc_transform(N, V, ltc), P, centre, normal, radius) *
             matc_fresnel_preintegrated_{{name}}(bbar, coat_bbar, NdotV) +
         matc_ltc_disk_integral(matc_ltc_transform(N, V, coat_ltc), P, centre, normal, radius) *
             matc_coat_fresnel_preintegrated_{{name}}(coat_bbar);
}

// ... and a sphere light.
float3 matc_ltc_sphere_light_{{name}}(float4 bbar, float4 coat_bbar, float4 ltc, float4 coat_ltc, float3 N,
                                    float3 V, float3 P, float3 centre, float radius) {
  float NdotV = clamp(dot(N, V), 0.0, 1.0);
  return matc_ltc_sphere_integral(matc_ltc_transform(N, V, ltc), P, centre, radius) *
             matc_fresnel_preintegrated_{{name}}(bbar, coat_bbar, NdotV) +
         matc_ltc_sphere_integral(matc_ltc_transform(N, V, coat_ltc), P, centre, radius) *
             matc_coat_fresnel_preintegrated_{{name}}(coat_bbar);
}
#endif
#endif  // MATC_MATERIAL_{{name}}
