
// Where its bbar is: this material's layer of the table, the {{basis}} basis'.
fn matc_lut_texcoord_{{name}}(NdotV: f32, roughness: f32) -> vec2f {
  return matc_lut_texcoord{{suffix}}(NdotV, roughness);
}
