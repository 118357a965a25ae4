
// The preintegrated table itself ({{embedded_size}}x{{embedded_size}}, --embed-lut){{of_basis}}, for shaders
// that cannot bind one more texture: row-major texels bbar_0..bbar_3, same axes as matc_lut.*.
const MATC_EMBEDDED_LUT_SIZE{{suffix}}: i32 = {{embedded_size}};
const MATC_EMBEDDED_LUT{{suffix}} = array<vec4f, {{embedded_texels}}>(
{{embedded_texel_values}});

fn matc_embedded_lut_texel{{suffix}}(x: i32, y: i32) -> vec4f {
  return MATC_EMBEDDED_LUT{{suffix}}[y * MATC_EMBEDDED_LUT_SIZE{{suffix}} + x];
}

// bbar_0..bbar_3 at (NdotV, roughness), filtered bilinearly by hand as a sampler would.
fn matc_preintegrated_basis_embedded{{suffix}}(NdotV: f32, roughness: f32) -> vec4f {
  let position = vec2f(sqrt(clamp(NdotV, 0.0, 1.0)), clamp(roughness, 0.0, 1.0)) *
                 f32(MATC_EMBEDDED_LUT_SIZE{{suffix}} - 1);
  let corner = min(vec2i(position), vec2i(MATC_EMBEDDED_LUT_SIZE{{suffix}} - 2));
  let f = position - vec2f(corner);
  let bottom = mix(matc_embedded_lut_texel{{suffix}}(corner.x, corner.y),
                   matc_embedded_lut_texel{{suffix}}(corner.x + 1, corner.y), f.x);
  let top = mix(matc_embedded_lut_texel{{suffix}}(corner.x, corner.y + 1),
                matc_embedded_lut_texel{{suffix}}(corner.x + 1, corner.y + 1), f.x);
  return mix(bottom, top, f.y);
}
