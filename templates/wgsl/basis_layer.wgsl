// The {{basis}} basis, layer {{layer}} of the table (matc --basis auto): the functions of the
// materials whose <name>.json names {{basis}}, each the first basis' function with _{{basis}}
// appended. Their snippets call them.
{{basis_function}}
fn matc_lut_texcoord_{{basis}}(NdotV: f32, roughness: f32) -> vec2f {
  return matc_lut_layer_texcoord(NdotV, roughness, {{layer}}.0);
}
{{analytic_lut}}{{area_light}}{{embedded_lut}}
