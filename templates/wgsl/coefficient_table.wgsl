
// ---- Textured and animated metals: coefficients at run time from the coefficient table. ----
// Width and height of the coefficient table this build writes (matc_coefficient_table.*).
const MATC_COEFFICIENT_TABLE_SIZE: i32 = {{coefficient_table_size}};

// Where to sample the coefficient table for one colour channel's reflectivity r and edge tint g
// (Gulbrandsen 2014), with linear filtering and clamp-to-edge addressing, texel centres on the
// ends of both axes: u = r^(1/3) across; down, how far g moves the index of refraction from
// n_max(r) towards n_min(r) in log n, v = log(1 - g delta) / log(1 - delta) with
// delta = 1 - n_min / n_max = 2 sqrt(r) / (1 + r). Below delta = 0.01 (r < 2.5e-5) v is its
// series in delta, which float logs of numbers that close to 1 could not resolve.
fn matc_coefficient_table_texcoord(r: f32, g: f32) -> vec2f {
  let reflectivity = clamp(r, 0.0, 1.0);
  let edge_tint = clamp(g, 0.0, 1.0);
  let sqrt_r = sqrt(reflectivity);
  let delta = 2.0 * sqrt_r / (1.0 + reflectivity);
  let series = edge_tint * (1.0 + edge_tint * delta * (0.5 + edge_tint * delta / 3.0)) /
               (1.0 + delta * (0.5 + delta / 3.0));
  // 1 - delta and 1 - g delta written so that r -> 1 does not cancel.
  let rest = (1.0 - sqrt_r) * (1.0 - sqrt_r) / (1.0 + reflectivity);
  let logs = log2(max((1.0 - edge_tint) + edge_tint * rest, 1e-30)) / log2(max(rest, 1e-30));
  let axes = vec2f(pow(reflectivity, 1.0 / 3.0), clamp(select(logs, series, delta < 0.01), 0.0, 1.0));
  // texcoord = (axes * (size - 1) + 0.5) / size, written as one multiply-add.
  return axes * (f32(MATC_COEFFICIENT_TABLE_SIZE - 1) / f32(MATC_COEFFICIENT_TABLE_SIZE)) + 0.5 / f32(MATC_COEFFICIENT_TABLE_SIZE);
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
