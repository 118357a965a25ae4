
// ---- Textured and animated metals: coefficients at run time from the coefficient table. ----
// Width and height of the coefficient table this build writes (matc_coefficient_table.*).
#define MATC_COEFFICIENT_TABLE_SIZE {{coefficient_table_size}}

// Where to sample the coefficient table for one colour channel's reflectivity r and edge tint g
// (Gulbrandsen 2014), with linear filtering and clamp-to-edge addressing, texel centres on the
// ends of both axes: u = (r^(1/4) + r^2) / 2 across (texels crowd near r = 0, where the curves
// change fastest, and near r = 1, where the coefficients do), v = 1 - sqrt(1 - g) down (rows
// crowd towards g = 1, where the index of refraction falls fastest). Three square roots and a
// few multiply-adds (issue #28).
float2 matc_coefficient_table_texcoord(float r, float g) {
  float reflectivity = saturate(r);
  // texcoord = (axis * (size - 1) + 0.5) / size, folded into each axis' multiply-adds.
  const float scale = float(MATC_COEFFICIENT_TABLE_SIZE - 1) / float(MATC_COEFFICIENT_TABLE_SIZE);
  const float offset = 0.5 / float(MATC_COEFFICIENT_TABLE_SIZE);
  float u = (0.5 * scale) * (sqrt(sqrt(reflectivity)) + reflectivity * reflectivity) + offset;
  float v = (scale + offset) - scale * sqrt(1.0 - saturate(g));
  return float2(u, v);
}

// One channel's c_0..c_3: c_0 = r, c_1 = 1 - r, and (c_2, c_3) the table's texel (its .xy) at
// matc_coefficient_table_texcoord(r, g).
float4 matc_channel_coefficients(float r, float2 texel) {
  float reflectivity = saturate(r);
  return float4(reflectivity, 1.0 - reflectivity, texel);
}

// A textured metal's coefficients from per-channel reflectivity r (its base colour) and the
// three channels' table texels; everything downstream (matc_fresnel, matc_fresnel_preintegrated,
// matc_energy_compensation) takes the result as it takes a compiled material's.
MatcFresnelCoefficients matc_coefficients_from_table(float3 r, float2 red, float2 green,
                                                     float2 blue) {
  MatcFresnelCoefficients c;
  c.red = matc_channel_coefficients(r.x, red);
  c.green = matc_channel_coefficients(r.y, green);
  c.blue = matc_channel_coefficients(r.z, blue);
  return c;
}

// The same with the three fetches from TABLE (a Texture2D) through SAMPLER (a SamplerState).
// R and G (float3) are evaluated more than once: pass variables.
#define MATC_COEFFICIENTS_FROM_TABLE(TABLE, SAMPLER, R, G)                                        \
  matc_coefficients_from_table(                                                                  \
      (R), TABLE.SampleLevel(SAMPLER, matc_coefficient_table_texcoord((R).x, (G).x), 0.0).xy,    \
      TABLE.SampleLevel(SAMPLER, matc_coefficient_table_texcoord((R).y, (G).y), 0.0).xy,         \
      TABLE.SampleLevel(SAMPLER, matc_coefficient_table_texcoord((R).z, (G).z), 0.0).xy)

// Reflectivity and edge tint per colour channel.
struct MatcArtistic {
  float3 reflectivity;
  float3 edge_tint;
};

// Gulbrandsen's inverse mapping: a complex IOR n + ik per channel (e.g. from n and k textures)
// to r = F0 and g = (n_max(r) - n) / (n_max(r) - n_min(r)), both clamped to [0, 1]; written
// without the division by 1 - sqrt(r) so that r -> 1 stays finite.
MatcArtistic matc_artistic_from_ior(float3 n, float3 k) {
  float3 k2 = k * k;
  float3 r = saturate(((n - 1.0) * (n - 1.0) + k2) / ((n + 1.0) * (n + 1.0) + k2));
  float3 sqrt_r = sqrt(r);
  float3 above = (1.0 + sqrt_r) * (1.0 + r) - n * (1.0 - sqrt_r) * (1.0 + r);
  float3 span = (1.0 + sqrt_r) * (1.0 + r) - (1.0 - r) * (1.0 - sqrt_r);
  MatcArtistic artistic;
  artistic.reflectivity = r;
  artistic.edge_tint = span > 0.0 ? saturate(above / max(span, 1e-30)) : 0.0;
  return artistic;
}
