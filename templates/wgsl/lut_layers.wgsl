// The table holds MATC_LUT_LAYERS bases side by side (matc --basis auto), each MATC_LUT_SIZE
// texels wide: layer k in columns [k size, (k + 1) size). Each material's <name>.json names its
// basis, and its snippet's matc_lut_texcoord_<name> samples that layer. Linear filtering and
// clamp-to-edge addressing: u = sqrt(NdotV) across, perceptual roughness down, texel centres on
// the ends of both axes of each layer, so filtering never reads the next layer.
const MATC_LUT_LAYERS: i32 = {{lut_layers}};
fn matc_lut_layer_texcoord(NdotV: f32, roughness: f32, layer: f32) -> vec2f {
  let axes = vec2f(sqrt(clamp(NdotV, 0.0, 1.0)), clamp(roughness, 0.0, 1.0));
  // ((axes (size - 1) + 0.5) / size + (layer, 0)) / (layers, 1), written as one multiply-add:
  // with `layer` a constant, as its callers give it, no more than one layer's costs.
  let size = vec2f(f32(MATC_LUT_SIZE * MATC_LUT_LAYERS), f32(MATC_LUT_SIZE));
  return axes * (f32(MATC_LUT_SIZE - 1) / size) + (vec2f(0.5 + layer * f32(MATC_LUT_SIZE), 0.5) / size);
}
// The first layer: that of matc_basis and matc_fresnel above.
fn matc_lut_texcoord(NdotV: f32, roughness: f32) -> vec2f {
  return matc_lut_layer_texcoord(NdotV, roughness, 0.0);
}

