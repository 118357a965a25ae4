#version 450
// matc {{version}}: the baked-texture render (examples/render/baked_render.cpp): a ground plane
// textured with a metal's reflectivity and edge-tint maps, seen in perspective so that texels
// shrink below a pixel towards the horizon, and F at one cosine per pixel. Methods:
//   0: ours: the coefficient textures of `matc bake` (F0, C2, C3) sampled with trilinear
//      filtering, matc_coefficients_from_baked, matc_fresnel
//   1: the usual way: mip chains of the maps themselves (linear r and g, box-averaged), sampled
//      with the same sampler, then per pixel MATC_COEFFICIENTS_FROM_TABLE and matc_fresnel
//   2: the exact curves filtered the same way: a texture of each texel's exact F at this
//      cosine with box-averaged mips, the same sampler (the best any prefiltered map does)
// Sky pixels (no plane) write alpha 0.
{{library}}
layout(set = 0, binding = 0) uniform texture2D baked_f0;
layout(set = 0, binding = 1) uniform texture2D baked_c2;
layout(set = 0, binding = 2) uniform texture2D baked_c3;
layout(set = 0, binding = 3) uniform texture2D map_reflectivity;
layout(set = 0, binding = 4) uniform texture2D map_edge_tint;
layout(set = 0, binding = 5) uniform texture2D matc_coefficient_table;
layout(set = 0, binding = 6) uniform sampler trilinear;      // trilinear, repeat
layout(set = 0, binding = 7) uniform sampler table_sampler;  // bilinear, clamp, one level
layout(set = 0, binding = 8) uniform texture2D exact_fresnel;
layout(push_constant) uniform Panel {
  int method;
  float mu;
} panel;
layout(location = 0) out vec4 result;

// The camera (baked_render.cpp's plane_uv, in float): at height {{camera_height}} above the
// plane z = 0, pitched {{pitch}} rad down, vertical field of view 2 atan({{tan_half_fov}}).
vec2 plane_uv(vec2 pixel, out bool hit) {
  vec2 size = vec2({{width}}.0, {{height}}.0);
  float sx = (2.0 * pixel.x / size.x - 1.0) * {{tan_half_fov}} * size.x / size.y;
  float sy = (1.0 - 2.0 * pixel.y / size.y) * {{tan_half_fov}};
  float c = cos({{pitch}}), s = sin({{pitch}});
  vec3 direction = vec3(sx, c + sy * s, -s + sy * c);
  hit = direction.z < -1e-4;
  float t = {{camera_height}} / max(-direction.z, 1e-4);
  return vec2(t * direction.x, t * direction.y) * {{uv_per_unit}};
}

void main() {
  bool hit;
  vec2 uv = plane_uv(gl_FragCoord.xy, hit);
  if (!hit) {
    result = vec4(0.0);
    return;
  }
  if (panel.method == 2) {
    result = vec4(texture(sampler2D(exact_fresnel, trilinear), uv).rgb, 1.0);
    return;
  }
  MatcFresnelCoefficients c;
  if (panel.method == 0) {
    vec3 f0 = texture(sampler2D(baked_f0, trilinear), uv).rgb;
    vec3 c2 = texture(sampler2D(baked_c2, trilinear), uv).rgb;
    vec3 c3 = texture(sampler2D(baked_c3, trilinear), uv).rgb;
    c = matc_coefficients_from_baked(f0, c2, c3);
  } else {
    vec3 r = texture(sampler2D(map_reflectivity, trilinear), uv).rgb;
    vec3 g = texture(sampler2D(map_edge_tint, trilinear), uv).rgb;
    c = MATC_COEFFICIENTS_FROM_TABLE(sampler2D(matc_coefficient_table, table_sampler), r, g);
  }
  result = vec4(matc_fresnel(c, panel.mu), 1.0);
}
