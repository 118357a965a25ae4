// Where to sample the preintegrated table, with linear filtering and clamp-to-edge addressing:
// u = sqrt(NdotV) across, perceptual roughness down, texel centres on the ends of both axes.
fn matc_lut_texcoord(NdotV: f32, roughness: f32) -> vec2f {
  let axes = vec2f(sqrt(clamp(NdotV, 0.0, 1.0)), clamp(roughness, 0.0, 1.0));
  // texcoord = (axes * (size - 1) + 0.5) / size, written as one multiply-add.
  return axes * (f32(MATC_LUT_SIZE - 1) / f32(MATC_LUT_SIZE)) + 0.5 / f32(MATC_LUT_SIZE);
}
