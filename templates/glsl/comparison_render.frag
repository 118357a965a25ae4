#version 450
// matc {{version}}: one panel of the comparison renders (examples/render) for material {{name}}:
// a sphere under a procedural sky, seen head-on, GGX with roughness from the push constants.
// Each method writes one estimate per pixel:
//   0: the Monte-Carlo reference, visible-normal sampling, exact Fresnel (tabulated curve)
//   1: Karis' prefiltered radiance (the split sum's first factor)
//   2: the exact preintegrated Fresnel, by visible-normal sampling (the best any split sum does)
//   3: Schlick's preintegrated Fresnel, from the ComparisonLobes table
//   4: ours, matc_fresnel_preintegrated_{{name}} from our table
//   5: ours from the table's closed form, matc_preintegrated_basis_analytic (no fetch)
// A filmed metal (MATC_RENDER_FILM 1) reads its own table at binding 4 for both 4 and 5: it has no
// closed form (docs/thin-film.md).
// Each pass writes (sum, weight) for its share of the samples; the host adds passes up and
// divides, and multiplies radiance by a Fresnel factor for the split-sum images. Background
// pixels write a negative weight.
{{film}}
{{library}}
{{material}}
layout(set = 0, binding = 0) uniform texture2D matc_lut;
layout(set = 0, binding = 1) uniform texture2D lobe_lut;  // ComparisonLobes: x albedo, y Schlick
layout(set = 0, binding = 2) uniform sampler matc_lut_sampler;
// The exact RGB curve at mu_j = j / (n - 1), linearly interpolated.
layout(std430, set = 0, binding = 3) readonly buffer ExactCurve { vec4 exact_curve[]; };
#if MATC_RENDER_FILM
layout(set = 0, binding = 4) uniform texture2D film_table;
#endif
layout(push_constant) uniform Panel {
  int method;
  uint first_sample;
  uint sample_count;
  uint total_samples;
  float roughness;
} panel;
layout(location = 0) out vec4 result;

const vec3 F0 = vec3({{f0}});
const uint CURVE_SIZE = {{curve_size}}u;
const vec2 SIZE = vec2({{width}}.0, {{height}}.0);
const float SPHERE_RADIUS = 0.92;  // of the half-width

{{render_sampling}}

vec3 exact_fresnel(float mu) {
  float x = clamp(mu, 0.0, 1.0) * float(CURVE_SIZE - 1u);
  uint i = min(uint(x), CURVE_SIZE - 2u);
  return mix(exact_curve[i].rgb, exact_curve[i + 1u].rgb, x - float(i));
}

void main() {
  vec2 p = (gl_FragCoord.xy / SIZE * 2.0 - 1.0) / SPHERE_RADIUS;
  p.y = -p.y;
  float r2 = dot(p, p);
  if (r2 >= 1.0) {
    result = vec4(-0.04, -0.04, -0.045, -1.0);
    return;
  }
  vec3 n = vec3(p, sqrt(1.0 - r2));
  vec3 v = vec3(0.0, 0.0, 1.0);
  float alpha = max(panel.roughness * panel.roughness, 1e-3);
  uvec2 pixel = uvec2(gl_FragCoord.xy);
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
        // E[L F G2/G1] with height-correlated Smith G2, as the table is baked.
        float g2_over_g1 = (1.0 + lambda_v) / (1.0 + lambda_v + smith_lambda(l.z, alpha));
        vec3 f = exact_fresnel(dot(view, h)) * g2_over_g1;
        sum += panel.method == 0 ? environment(l.x * t + l.y * b + l.z * n) * f : f;
      }
    }
    weight = float(panel.sample_count);
  } else if (panel.method == 1) {
    // Karis 2013: radiance prefiltered around the mirror direction with N = V = R.
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
      sum = F0 * lobes.x + (vec3(1.0) - F0) * lobes.y;
    } else {
#if MATC_RENDER_FILM
      sum = matc_fresnel_preintegrated_{{name}}(MATC_FILM_PREINTEGRATED(
          sampler2D(film_table, matc_lut_sampler), n.z, panel.roughness));
#else
      sum = matc_fresnel_preintegrated_{{name}}(
          panel.method == 5 ? matc_preintegrated_basis_analytic(n.z, panel.roughness)
                            : textureLod(sampler2D(matc_lut, matc_lut_sampler), texcoord, 0.0));
#endif
    }
    weight = 1.0;
  }
  result = vec4(sum, weight);
}
