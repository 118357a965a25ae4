
// ---- Textured metals, solved offline: the coefficient textures of `matc bake`. ----
// Sample NAME_c2, NAME_c3 (and NAME_f0, or the engine's base colour, when its mips are box
// averages of linear F0) with one trilinear sampler at the same texture coordinate; each mip
// texel averages coefficients, so it holds the average of the Fresnel curves it covers.
MatcFresnelCoefficients matc_coefficients_from_baked(float3 f0, float3 c2, float3 c3) {
  float3 c0 = saturate(f0);
  MatcFresnelCoefficients c;
  c.red = float4(c0.x, 1.0 - c0.x, c2.x, c3.x);
  c.green = float4(c0.y, 1.0 - c0.y, c2.y, c3.y);
  c.blue = float4(c0.z, 1.0 - c0.z, c2.z, c3.z);
  return c;
}

// ---- Textured metals of Schlick's curve (a glTF metal's base colour), per pixel. ----
// Schlick's curve is linear in F0, and so are its coefficients: per channel F0 (1, 0, 0, 0) +
// (1 - F0) times the curve's coefficients at F0 = 0 (MATC_materials_fresnel's zeroF0Coefficients,
// docs/gltf.md). F0 is the material's base colour (factor times texture, linear), clamped to [0, 1].
MatcFresnelCoefficients matc_coefficients_from_f0(MatcFresnelCoefficients zero_f0, float3 f0) {
  float3 c0 = saturate(f0);
  MatcFresnelCoefficients c;
  c.red = float4(c0.x, 0.0, 0.0, 0.0) + (1.0 - c0.x) * zero_f0.red;
  c.green = float4(c0.y, 0.0, 0.0, 0.0) + (1.0 - c0.y) * zero_f0.green;
  c.blue = float4(c0.z, 0.0, 0.0, 0.0) + (1.0 - c0.z) * zero_f0.blue;
  return c;
}
