
// The preintegrated table itself ({{embedded_size}}x{{embedded_size}}, --embed-lut), for shaders
// that cannot bind one more texture: row-major texels bbar_0..bbar_3, same axes as matc_lut.*.
const MATC_EMBEDDED_LUT_SIZE: i32 = {{embedded_size}};
const MATC_EMBEDDED_LUT = array<vec4f, {{embedded_texels}}>(
{{embedded_texel_values}});

fn matc_embedded_lut_texel(x: i32, y: i32) -> vec4f {
  return MATC_EMBEDDED_LUT[y * MATC_EMBEDDED_LUT_SIZE + x];
}

// bbar_0..bbar_3 at (NdotV, roughness), filtered bilinearly by hand as a sampler would.
fn matc_preintegrated_basis_embedded(NdotV: f32, roughness: f32) -> vec4f {
  let position = vec2f(sqrt(clamp(NdotV, 0.0, 1.0)), clamp(roughness, 0.0, 1.0)) *
                 f32(MATC_EMBEDDED_LUT_SIZE - 1);
  let corner = min(vec2i(position), vec2i(MATC_EMBEDDED_LUT_SIZE - 2));
  let f = position - vec2f(corner);
  let bottom = mix(matc_embedded_lut_texel(corner.x, corner.y),
                   matc_embedded_lut_texel(corner.x + 1, corner.y), f.x);
  let top = mix(matc_embedded_lut_texel(corner.x, corner.y + 1),
                matc_embedded_lut_texel(corner.x + 1, corner.y + 1), f.x);
  return mix(bottom, top, f.y);
}
