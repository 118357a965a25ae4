
// ---- Textured metals, solved offline: the coefficient textures of `matc bake`. ----
// Sample NAME_c2, NAME_c3 (and NAME_f0, or the engine's base colour, when its mips are box
// averages of linear F0) with one trilinear sampler at the same texture coordinate; each mip
// texel averages coefficients, so it holds the average of the Fresnel curves it covers.
fn matc_coefficients_from_baked(f0: vec3f, c2: vec3f, c3: vec3f) -> MatcFresnelCoefficients {
  let c0 = clamp(f0, vec3f(0.0), vec3f(1.0));
  return MatcFresnelCoefficients(vec4f(c0.x, 1.0 - c0.x, c2.x, c3.x),
                                 vec4f(c0.y, 1.0 - c0.y, c2.y, c3.y),
                                 vec4f(c0.z, 1.0 - c0.z, c2.z, c3.z));
}
