// Where to sample the preintegrated table, with linear filtering and clamp-to-edge addressing:
// u = sqrt(NdotV) across, perceptual roughness down, texel centres on the ends of both axes.
float2 matc_lut_texcoord(float NdotV, float roughness) {
  float2 axes = float2(sqrt(saturate(NdotV)), saturate(roughness));
  // texcoord = (axes * (size - 1) + 0.5) / size, written as one multiply-add.
  return axes * (float(MATC_LUT_SIZE - 1) / float(MATC_LUT_SIZE)) + 0.5 / float(MATC_LUT_SIZE);
}
