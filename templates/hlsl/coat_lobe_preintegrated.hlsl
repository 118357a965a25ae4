// The coat lobe's preintegrated F, its weight included.
float matc_coat_fresnel_preintegrated_{{name}}(float4 coat_bbar) {
  float f = clamp(dot(matc_coat_coefficients_{{name}}, coat_bbar), 0.0, 1.0);
  return matc_coat_weight_{{name}} * f;
}
