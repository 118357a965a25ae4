// Where to sample the preintegrated table, with linear filtering and clamp-to-edge addressing:
// u = sqrt(NdotV) across, perceptual roughness down, texel centres on the ends of both axes.
vec2 matc_lut_texcoord(float NdotV, float roughness) {
  vec2 axes = vec2(sqrt(clamp(NdotV, 0.0, 1.0)), clamp(roughness, 0.0, 1.0));
  // texcoord = (axes * (size - 1) + 0.5) / size, written as one multiply-add.
  return axes * (float(MATC_LUT_SIZE - 1) / float(MATC_LUT_SIZE)) + 0.5 / float(MATC_LUT_SIZE);
}
