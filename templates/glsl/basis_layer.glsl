// The {{basis}} basis, layer {{layer}} of the table (matc --basis auto): the functions of the
// materials whose <name>.json names {{basis}}, each the first basis' function with _{{basis}}
// appended. Their snippets call them.
{{basis_function}}
vec2 matc_lut_texcoord_{{basis}}(float NdotV, float roughness) {
  return matc_lut_layer_texcoord(NdotV, roughness, {{layer}}.0);
}
{{analytic_lut}}{{area_light}}{{embedded_lut}}
