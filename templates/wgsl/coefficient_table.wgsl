
// ---- Textured and animated metals: coefficients at run time from the coefficient table. ----
// Width and height of the coefficient table this build writes (matc_coefficient_table.*).
const MATC_COEFFICIENT_TABLE_SIZE: i32 = {{coefficient_table_size}};

// Where to sample the coefficient table for one colour channel's reflectivity r and edge tint g
// (Gulbrandsen 2014), with linear filtering and clamp-to-edge addressing, texel centres on the
// ends of both axes: u = (r^(1/4) + r^2) / 2 across (texels crowd near r = 0, where the curves
// change fastest, and near r = 1, where the coefficients do), v = 1 - sqrt(1 - g) down (rows
// crowd towards g = 1, where the index of refraction falls fastest). Three square roots and a
// few multiply-adds (issue #28).
fn matc_coefficient_table_texcoord(r: f32, g: f32) -> vec2f {
  let reflectivity = clamp(r, 0.0, 1.0);
  // texcoord = (axis * (size - 1) + 0.5) / size, folded into each axis' multiply-adds.
  let scale = f32(MATC_COEFFICIENT_TABLE_SIZE - 1) / f32(MATC_COEFFICIENT_TABLE_SIZE);
  let offset = 0.5 / f32(MATC_COEFFICIENT_TABLE_SIZE);
  let u = (0.5 * scale) * (sqrt(sqrt(reflectivity)) + reflectivity * reflectivity) + offset;
  let v = (scale + offset) - scale * sqrt(1.0 - clamp(g, 0.0, 1.0));
  return vec2f(u, v);
}

// One channel's c_0..c_3: c_0 = r, c_1 = 1 - r, and (c_2, c_3) the table's texel (its .xy) at
// matc_coefficient_table_texcoord(r, g).
fn matc_channel_coefficients(r: f32, texel: vec2f) -> vec4f {
  let reflectivity = clamp(r, 0.0, 1.0);
  return vec4f(reflectivity, 1.0 - reflectivity, texel);
}

// A textured metal's coefficients from per-channel reflectivity r (its base colour) and the
// three channels' table texels; everything downstream (matc_fresnel, matc_fresnel_preintegrated,
// matc_energy_compensation) takes the result as it takes a compiled material's.
fn matc_coefficients_from_table(r: vec3f, red: vec2f, green: vec2f,
                                blue: vec2f) -> MatcFresnelCoefficients {
  return MatcFresnelCoefficients(matc_channel_coefficients(r.x, red),
                                 matc_channel_coefficients(r.y, green),
                                 matc_channel_coefficients(r.z, blue));
}

// The same with the three fetches (GLSL's and HLSL's MATC_COEFFICIENTS_FROM_TABLE): the table
// bound with a linear, clamp-to-edge sampler. An rg32float table needs the device feature
// "float32-filterable"; the f16 table (--coefficient-table-precision f16, the default) does not.
fn matc_coefficients_from_table_texture(table: texture_2d<f32>, table_sampler: sampler, r: vec3f,
                                        g: vec3f) -> MatcFresnelCoefficients {
  return matc_coefficients_from_table(
      r,
      textureSampleLevel(table, table_sampler, matc_coefficient_table_texcoord(r.x, g.x), 0.0).xy,
      textureSampleLevel(table, table_sampler, matc_coefficient_table_texcoord(r.y, g.y), 0.0).xy,
      textureSampleLevel(table, table_sampler, matc_coefficient_table_texcoord(r.z, g.z), 0.0).xy);
}

// Reflectivity and edge tint per colour channel.
struct MatcArtistic {
  reflectivity: vec3f,
  edge_tint: vec3f,
}

// Gulbrandsen's inverse mapping: a complex IOR n + ik per channel (e.g. from n and k textures)
// to r = F0 and g = (n_max(r) - n) / (n_max(r) - n_min(r)), both clamped to [0, 1]; written
// without the division by 1 - sqrt(r) so that r -> 1 stays finite.
fn matc_artistic_from_ior(n: vec3f, k: vec3f) -> MatcArtistic {
  let k2 = k * k;
  let r = clamp(((n - 1.0) * (n - 1.0) + k2) / ((n + 1.0) * (n + 1.0) + k2), vec3f(0.0),
                vec3f(1.0));
  let sqrt_r = sqrt(r);
  let above = (1.0 + sqrt_r) * (1.0 + r) - n * (1.0 - sqrt_r) * (1.0 + r);
  let span = (1.0 + sqrt_r) * (1.0 + r) - (1.0 - r) * (1.0 - sqrt_r);
  let g = select(vec3f(0.0), clamp(above / max(span, vec3f(1e-30)), vec3f(0.0), vec3f(1.0)),
                 span > vec3f(0.0));
  return MatcArtistic(r, g);
}
