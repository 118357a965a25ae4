
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

// ---- Textured metals under an edge colour or a coat, per pixel: the F0 table. ----
// MATC_materials_fresnel's f0Table (docs/gltf.md): the metal compiled at 33 values of F0, entry i
// at F0 = (i / 32)^4; a pixel's coefficients interpolate, per channel, the two entries around
// F0^(1/4). As a texture: RGBA32F, 33 x 6, texel (i, c) entry i's row of channel c in air and
// (i, 3 + c) under the coat, read with Load (the interpolation is here, not the sampler's).
// Where along the entries F0 falls (0 to 32), and the entry on its left (0 to 31).
float matc_f0_table_position(float f0) {
  return sqrt(sqrt(saturate(f0))) * 32.0;
}
int matc_f0_table_left(float position) {
  return min(int(position), 31);
}
float4 matc_f0_table_mix(float4 left, float4 right, float f0) {
  float position = matc_f0_table_position(f0);
  return lerp(left, right, position - float(matc_f0_table_left(position)));
}
// From each channel's entries left and right of its F0. In air c_0 = F0 and c_1 = 1 - F0 exactly
// (the curve's values head on and at grazing); under the coat all four are interpolated.
MatcFresnelCoefficients matc_coefficients_from_f0_entries(float3 f0, MatcFresnelCoefficients left,
                                                          MatcFresnelCoefficients right) {
  float3 c0 = saturate(f0);
  MatcFresnelCoefficients c;
  c.red = float4(c0.x, 1.0 - c0.x, matc_f0_table_mix(left.red, right.red, f0.x).zw);
  c.green = float4(c0.y, 1.0 - c0.y, matc_f0_table_mix(left.green, right.green, f0.y).zw);
  c.blue = float4(c0.z, 1.0 - c0.z, matc_f0_table_mix(left.blue, right.blue, f0.z).zw);
  return c;
}
MatcFresnelCoefficients matc_under_coat_from_f0_entries(float3 f0, MatcFresnelCoefficients left,
                                                        MatcFresnelCoefficients right) {
  MatcFresnelCoefficients c;
  c.red = matc_f0_table_mix(left.red, right.red, f0.x);
  c.green = matc_f0_table_mix(left.green, right.green, f0.y);
  c.blue = matc_f0_table_mix(left.blue, right.blue, f0.z);
  return c;
}
// The entries left (next 0) or right (next 1) of each channel's F0, from rows row to row + 2.
MatcFresnelCoefficients matc_f0_table_entries(Texture2D<float4> table, float3 f0, int row, int next) {
  MatcFresnelCoefficients c;
  c.red = table.Load(int3(matc_f0_table_left(matc_f0_table_position(f0.x)) + next, row, 0));
  c.green = table.Load(int3(matc_f0_table_left(matc_f0_table_position(f0.y)) + next, row + 1, 0));
  c.blue = table.Load(int3(matc_f0_table_left(matc_f0_table_position(f0.z)) + next, row + 2, 0));
  return c;
}
MatcFresnelCoefficients matc_coefficients_from_f0_table(Texture2D<float4> table, float3 f0) {
  return matc_coefficients_from_f0_entries(f0, matc_f0_table_entries(table, f0, 0, 0),
                                           matc_f0_table_entries(table, f0, 0, 1));
}
MatcFresnelCoefficients matc_under_coat_from_f0_table(Texture2D<float4> table, float3 f0) {
  return matc_under_coat_from_f0_entries(f0, matc_f0_table_entries(table, f0, 3, 0),
                                         matc_f0_table_entries(table, f0, 3, 1));
}
