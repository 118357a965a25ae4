#version 450
// matc {{version}}: one panel of the textured render (examples/render/textured_render.cpp): the
// sphere of the comparison renders, but its reflectivity r and edge tint g (Gulbrandsen) change
// from pixel to pixel, read from a buffer with one entry per pixel: (r.rgb, -), (g.rgb, -),
// (n.rgb, -), (k.rgb, -), n + ik Gulbrandsen's IOR of (r, g) computed on the host. Methods:
//   0: the Monte-Carlo reference with the exact conductor Fresnel of that pixel's n + ik
//   1: Karis' prefiltered radiance (the split sum's first factor)
//   2: the exact preintegrated Fresnel, by visible-normal sampling (the best any split sum does)
//   3: Schlick's preintegrated Fresnel with F0 = r, from the ComparisonLobes table
//   4: ours: MATC_COEFFICIENTS_FROM_TABLE(r, g) and matc_fresnel_preintegrated, the textured
//      metal path of the generated library
//   5: the same from the table's closed form, matc_preintegrated_basis_analytic (no fetch)
// Each pass writes (sum, weight) for its share of the samples, as comparison_render.frag does.
{{library}}
layout(set = 0, binding = 0) uniform texture2D matc_lut;
layout(set = 0, binding = 1) uniform texture2D lobe_lut;  // ComparisonLobes: x albedo, y Schlick
layout(set = 0, binding = 2) uniform sampler matc_lut_sampler;
layout(set = 0, binding = 3) uniform texture2D matc_coefficient_table;
layout(std430, set = 0, binding = 4) readonly buffer PixelMaterial { vec4 pixel_material[]; };
layout(push_constant) uniform Panel {
  int method;
  uint first_sample;
  uint sample_count;
  uint total_samples;
  float roughness;
} panel;
layout(location = 0) out vec4 result;

const vec2 SIZE = vec2({{width}}.0, {{height}}.0);
const float SPHERE_RADIUS = 0.92;  // of the half-width

{{render_sampling}}

// The exact Fresnel reflectance of a conductor n + ik (unpolarised; Born and Wolf, in the form
// of pbrt's FrComplex written out in real arithmetic).
float fresnel_conductor(float cos_i, float n, float k) {
  float c2 = cos_i * cos_i;
  float s2 = 1.0 - c2;
  float t0 = n * n - k * k - s2;
  float a2b2 = sqrt(t0 * t0 + 4.0 * n * n * k * k);
  float a = sqrt(max(0.5 * (a2b2 + t0), 0.0));
  float t1 = a2b2 + c2;
  float t2 = 2.0 * cos_i * a;
  float rs = (t1 - t2) / max(t1 + t2, 1e-30);
  float t3 = c2 * a2b2 + s2 * s2;
  float t4 = t2 * s2;
  float rp = rs * (t3 - t4) / max(t3 + t4, 1e-30);
  return 0.5 * (rp + rs);
}

void main() {
  vec2 p = (gl_FragCoord.xy / SIZE * 2.0 - 1.0) / SPHERE_RADIUS;
  p.y = -p.y;
  float r2 = dot(p, p);
  if (r2 >= 1.0) {
    result = vec4(-0.04, -0.04, -0.045, -1.0);
    return;
  }
  uvec2 pixel = uvec2(gl_FragCoord.xy);
  uint entry = 4u * (pixel.y * uint(SIZE.x) + pixel.x);
  vec3 reflectivity = pixel_material[entry].rgb;
  vec3 edge_tint = pixel_material[entry + 1u].rgb;
  vec3 ior_n = pixel_material[entry + 2u].rgb;
  vec3 ior_k = pixel_material[entry + 3u].rgb;
  vec3 n = vec3(p, sqrt(1.0 - r2));
  vec3 v = vec3(0.0, 0.0, 1.0);
  float alpha = max(panel.roughness * panel.roughness, 1e-3);
  vec2 shift = vec2(hash(pixel.x + 4096u * pixel.y), hash(pixel.y + 4096u * pixel.x + 17u)) *
               2.3283064365386963e-10;
  vec3 sum = vec3(0.0);
  float weight = 0.0;
  uint last = panel.first_sample + panel.sample_count;
  vec3 t, b;
  if (panel.method == 0 || panel.method == 2) {
    frame(n, t, b);
    vec3 view = vec3(dot(v, t), dot(v, b), max(dot(v, n), 1e-4));
    float lambda_v = smith_lambda(view.z, alpha);
    for (uint i = panel.first_sample; i < last; ++i) {
      vec3 h = sample_visible_normal(view, alpha, sample_point(i, panel.total_samples, shift));
      vec3 l = reflect(-view, h);
      if (l.z > 0.0) {
        float g2_over_g1 = (1.0 + lambda_v) / (1.0 + lambda_v + smith_lambda(l.z, alpha));
        float mu = clamp(dot(view, h), 0.0, 1.0);
        vec3 f = vec3(fresnel_conductor(mu, ior_n.r, ior_k.r),
                      fresnel_conductor(mu, ior_n.g, ior_k.g),
                      fresnel_conductor(mu, ior_n.b, ior_k.b)) * g2_over_g1;
        sum += panel.method == 0 ? environment(l.x * t + l.y * b + l.z * n) * f : f;
      }
    }
    weight = float(panel.sample_count);
  } else if (panel.method == 1) {
    vec3 r = reflect(-v, n);
    frame(r, t, b);
    for (uint i = panel.first_sample; i < last; ++i) {
      vec3 h = sample_normal(alpha, sample_point(i, panel.total_samples, shift));
      vec3 l = 2.0 * h.z * h - vec3(0.0, 0.0, 1.0);
      if (l.z > 0.0) {
        sum += environment(l.x * t + l.y * b + l.z * r) * l.z;
        weight += l.z;
      }
    }
  } else {
    vec2 texcoord = matc_lut_texcoord(n.z, panel.roughness);
    if (panel.method == 3) {
      vec4 lobes = textureLod(sampler2D(lobe_lut, matc_lut_sampler), texcoord, 0.0);
      sum = reflectivity * lobes.x + (vec3(1.0) - reflectivity) * lobes.y;
    } else {
      MatcFresnelCoefficients c = MATC_COEFFICIENTS_FROM_TABLE(
          sampler2D(matc_coefficient_table, matc_lut_sampler), reflectivity, edge_tint);
      vec4 bbar = panel.method == 5
                      ? matc_preintegrated_basis_analytic(n.z, panel.roughness)
                      : textureLod(sampler2D(matc_lut, matc_lut_sampler), texcoord, 0.0);
      sum = matc_fresnel_preintegrated(c, bbar);
    }
    weight = 1.0;
  }
  result = vec4(sum, weight);
}
