// The table holds MATC_LUT_LAYERS bases side by side (matc --basis auto), each MATC_LUT_SIZE
// texels wide: layer k in columns [k size, (k + 1) size). Each material's <name>.json names its
// basis, and its snippet's matc_lut_texcoord_<name> samples that layer. Linear filtering and
// clamp-to-edge addressing: u = sqrt(NdotV) across, perceptual roughness down, texel centres on
// the ends of both axes of each layer, so filtering never reads the next layer.
#define MATC_LUT_LAYERS {{lut_layers}}
float2 matc_lut_layer_texcoord(float NdotV, float roughness, float layer) {
  float2 axes = float2(sqrt(saturate(NdotV)), saturate(roughness));
  // ((axes (size - 1) + 0.5) / size + (layer, 0)) / (layers, 1), written as one multiply-add:
  // with `layer` a constant, as its callers give it, no more than one layer's costs.
  float2 size = float2(float(MATC_LUT_SIZE * MATC_LUT_LAYERS), float(MATC_LUT_SIZE));
  return axes * (float(MATC_LUT_SIZE - 1) / size) +
         (float2(0.5 + layer * float(MATC_LUT_SIZE), 0.5) / size);
}
// The first layer: that of matc_basis and matc_fresnel above.
float2 matc_lut_texcoord(float NdotV, float roughness) {
  return matc_lut_layer_texcoord(NdotV, roughness, 0.0);
}

