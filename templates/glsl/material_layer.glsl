
// Where its bbar is: this material's layer of the table, the {{basis}} basis'.
vec2 matc_lut_texcoord_{{name}}(float NdotV, float roughness) {
  return matc_lut_texcoord{{suffix}}(NdotV, roughness);
}
