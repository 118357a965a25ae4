
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

// ---- Textured metals of Schlick's curve (a glTF metal's base colour), per pixel. ----
// Schlick's curve is linear in F0, and so are its coefficients: per channel F0 (1, 0, 0, 0) +
// (1 - F0) times the curve's coefficients at F0 = 0 (MATC_materials_fresnel's zeroF0Coefficients,
// docs/gltf.md). F0 is the material's base colour (factor times texture, linear), clamped to [0, 1].
fn matc_coefficients_from_f0(zero_f0: MatcFresnelCoefficients, f0: vec3f) -> MatcFresnelCoefficients {
  let c0 = clamp(f0, vec3f(0.0), vec3f(1.0));
  return MatcFresnelCoefficients(vec4f(c0.x, 0.0, 0.0, 0.0) + (1.0 - c0.x) * zero_f0.red,
                                 vec4f(c0.y, 0.0, 0.0, 0.0) + (1.0 - c0.y) * zero_f0.green,
                                 vec4f(c0.z, 0.0, 0.0, 0.0) + (1.0 - c0.z) * zero_f0.blue);
}

// ---- Textured metals under an edge colour or a coat, per pixel: the F0 table. ----
// MATC_materials_fresnel's f0Table (docs/gltf.md): the metal compiled at 33 values of F0, entry i
// at F0 = (i / 32)^4; a pixel's coefficients interpolate, per channel, the two entries around
// F0^(1/4). As a texture: rgba32float, 33 x 6, texel (i, c) entry i's row of channel c in air and
// (i, 3 + c) under the coat, read with textureLoad (the interpolation is here, not a sampler's).
// Where along the entries F0 falls (0 to 32), and the entry on its left (0 to 31).
fn matc_f0_table_position(f0: f32) -> f32 {
  return sqrt(sqrt(clamp(f0, 0.0, 1.0))) * 32.0;
}
fn matc_f0_table_left(position: f32) -> i32 {
  return min(i32(position), 31);
}
fn matc_f0_table_mix(left: vec4f, right: vec4f, f0: f32) -> vec4f {
  let position = matc_f0_table_position(f0);
  return mix(left, right, position - f32(matc_f0_table_left(position)));
}
// From each channel's entries left and right of its F0. In air c_0 = F0 and c_1 = 1 - F0 exactly
// (the curve's values head on and at grazing); under the coat all four are interpolated.
fn matc_coefficients_from_f0_entries(f0: vec3f, left: MatcFresnelCoefficients,
                                     right: MatcFresnelCoefficients) -> MatcFresnelCoefficients {
  let c0 = clamp(f0, vec3f(0.0), vec3f(1.0));
  return MatcFresnelCoefficients(
      vec4f(c0.x, 1.0 - c0.x, matc_f0_table_mix(left.red, right.red, f0.x).zw),
      vec4f(c0.y, 1.0 - c0.y, matc_f0_table_mix(left.green, right.green, f0.y).zw),
      vec4f(c0.z, 1.0 - c0.z, matc_f0_table_mix(left.blue, right.blue, f0.z).zw));
}
fn matc_under_coat_from_f0_entries(f0: vec3f, left: MatcFresnelCoefficients,
                                   right: MatcFresnelCoefficients) -> MatcFresnelCoefficients {
  return MatcFresnelCoefficients(matc_f0_table_mix(left.red, right.red, f0.x),
                                 matc_f0_table_mix(left.green, right.green, f0.y),
                                 matc_f0_table_mix(left.blue, right.blue, f0.z));
}
// The entries left (next 0) or right (next 1) of each channel's F0, from rows row to row + 2.
fn matc_f0_table_entries(table: texture_2d<f32>, f0: vec3f, row: i32,
                         next: i32) -> MatcFresnelCoefficients {
  return MatcFresnelCoefficients(
      textureLoad(table, vec2i(matc_f0_table_left(matc_f0_table_position(f0.x)) + next, row), 0),
      textureLoad(table, vec2i(matc_f0_table_left(matc_f0_table_position(f0.y)) + next, row + 1), 0),
      textureLoad(table, vec2i(matc_f0_table_left(matc_f0_table_position(f0.z)) + next, row + 2), 0));
}
fn matc_coefficients_from_f0_table(table: texture_2d<f32>, f0: vec3f) -> MatcFresnelCoefficients {
  return matc_coefficients_from_f0_entries(f0, matc_f0_table_entries(table, f0, 0, 0),
                                           matc_f0_table_entries(table, f0, 0, 1));
}
fn matc_under_coat_from_f0_table(table: texture_2d<f32>, f0: vec3f) -> MatcFresnelCoefficients {
  return matc_under_coat_from_f0_entries(f0, matc_f0_table_entries(table, f0, 3, 0),
                                         matc_f0_table_entries(table, f0, 3, 1));
}
