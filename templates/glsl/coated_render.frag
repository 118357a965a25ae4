#version 450
// matc {{version}}: one panel of the coated comparison render (examples/render) for the coated
// material {{name}}: the sphere of comparison_render.frag under the same sky, two GGX lobes, the
// base's at the roughness of the push constants and the coat's at matc_coat_roughness_{{name}}.
// Each method writes one estimate per pixel:
//   0: the Monte-Carlo reference: both lobes as a direct light computes them (the base's GGX with
//      the layered base curve at v.h, the coat's GGX with its weight times its Fresnel at v.h),
//      by visible-normal sampling with the exact curves
//   1: Karis' prefiltered radiance at the base's roughness, 2: at the coat's
//   3, 4, 5: the exact preintegrated curves (visible-normal sampling) the layering of a split sum
//      combines: the metal under the coat (at the base's roughness), the coat's Fresnel (at the
//      coat's), the metal in air (at the base's); the host layers them as the shaders do
//   6: ours, the base lobe's matc_fresnel_preintegrated_{{name}}, 7: the coat lobe's
//   8: the engines' shortcut, the base's F0 converted into the coat with Schlick's curve, under
//      the same layering and coat lobe
//   9: the coat's tint at NdotV, matc_coat_tint_{{name}} (for the host's layering)
//   10, 11: three.js's clear coat (MeshPhysicalMaterial, as its glTF loader builds a
//      KHR_materials_clearcoat metal): the base lobe the metal's Schlick curve in air (F0, not
//      seen from the coat), attenuated once by the coat's Schlick Fresnel at NdotV (F0 0.04, its
//      clearcoatF0), no tint; the coat lobe that Fresnel preintegrated at the coat's roughness;
//      both times the weight as three.js applies it (with the exact split-sum table of Schlick's
//      curve, not three.js's analytic fit of it)
// Each pass writes (sum, weight) for its share of the samples; the host adds passes up, divides
// and multiplies each lobe's radiance by its Fresnel factor. Background pixels write a negative
// weight.
{{library}}
{{material}}
layout(set = 0, binding = 0) uniform texture2D matc_lut;
layout(set = 0, binding = 1) uniform texture2D lobe_lut;  // ComparisonLobes: x albedo, y Schlick
layout(set = 0, binding = 2) uniform sampler matc_lut_sampler;
// The exact curves at mu_j = j / (n - 1), linearly interpolated: entries 0 to n - 1 the metal under
// the coat (rgb, UnderCoatCurve) and the coat's Fresnel (a), n to 2n - 1 the metal in air (rgb).
layout(std430, set = 0, binding = 3) readonly buffer ExactCurve { vec4 exact_curve[]; };
layout(push_constant) uniform Panel {
  int method;
  uint first_sample;
  uint sample_count;
  uint total_samples;
  float roughness;
} panel;
layout(location = 0) out vec4 result;

const vec3 F0 = vec3({{f0}});                  // the metal's in air
const vec3 F0_IN_COAT = vec3({{f0_in_coat}});  // as engines convert it (f0_seen_from_coat)
const uint CURVE_SIZE = {{curve_size}}u;
const vec2 SIZE = vec2({{width}}.0, {{height}}.0);
const float SPHERE_RADIUS = 0.92;  // of the half-width

{{render_sampling}}

// The exact curves at mu: the first (under the coat, the coat) or the second (in air).
vec4 exact_at(float mu, uint curve) {
  float x = clamp(mu, 0.0, 1.0) * float(CURVE_SIZE - 1u);
  uint j = min(uint(x), CURVE_SIZE - 2u);
  uint i = j + curve * CURVE_SIZE;
  return mix(exact_curve[i], exact_curve[i + 1u], x - float(j));
}

// The layering the shaders apply (matc_coated_base_{{name}}): mix(in air, (1 - f)^2 v /
// (1 - f min(v, 1)), weight) with v the tinted metal under the coat, f the coat's Fresnel.
vec3 layered_base(vec3 in_air, vec3 v, float f) {
  f = clamp(f, 0.0, 1.0);
  v = max(v, vec3(0.0));
  vec3 through = (1.0 - f) * (1.0 - f) * v / max(vec3(1.0) - f * min(v, vec3(1.0)), vec3(1e-6));
  return mix(in_air, through, matc_coat_weight_{{name}});
}

// The curve a method samples at v.h: 0 both lobes' (`base`: the base lobe's, or the coat's),
// 3 the metal under the coat, 4 the coat's Fresnel, 5 the metal in air.
vec3 curve_at(int method, bool base, float mu) {
  vec4 under = exact_at(mu, 0u);
  if (method == 0) {
    return base ? layered_base(exact_at(mu, 1u).rgb, under.rgb * matc_coat_tint_{{name}}(mu), under.a)
                : vec3(matc_coat_weight_{{name}} * under.a);
  }
  return method == 3 ? under.rgb : method == 4 ? vec3(under.a) : exact_at(mu, 1u).rgb;
}

// E[L F G2/G1] (method 0) or E[F G2/G1] (3, 4, 5) of one lobe.
vec3 sample_lobe(vec3 n, vec3 v, float roughness, bool base, bool with_light, vec2 shift) {
  float alpha = max(roughness * roughness, 1e-3);
  vec3 t, b;
  frame(n, t, b);
  vec3 view = vec3(dot(v, t), dot(v, b), max(dot(v, n), 1e-4));
  float lambda_v = smith_lambda(view.z, alpha);
  vec3 sum = vec3(0.0);
  uint last = panel.first_sample + panel.sample_count;
  for (uint i = panel.first_sample; i < last; ++i) {
    vec3 h = sample_visible_normal(view, alpha, sample_point(i, panel.total_samples, shift));
    vec3 l = reflect(-view, h);
    if (l.z > 0.0) {
      float g2_over_g1 = (1.0 + lambda_v) / (1.0 + lambda_v + smith_lambda(l.z, alpha));
      vec3 f = curve_at(panel.method, base, dot(view, h)) * g2_over_g1;
      sum += with_light ? environment(l.x * t + l.y * b + l.z * n) * f : f;
    }
  }
  return sum;
}

// Karis 2013: radiance prefiltered around the mirror direction with N = V = R; (sum, weight).
vec4 prefiltered_radiance(vec3 n, vec3 v, float roughness, vec2 shift) {
  float alpha = max(roughness * roughness, 1e-3);
  vec3 r = reflect(-v, n);
  vec3 t, b;
  frame(r, t, b);
  vec4 sum = vec4(0.0);
  uint last = panel.first_sample + panel.sample_count;
  for (uint i = panel.first_sample; i < last; ++i) {
    vec3 h = sample_normal(alpha, sample_point(i, panel.total_samples, shift));
    vec3 l = 2.0 * h.z * h - vec3(0.0, 0.0, 1.0);
    if (l.z > 0.0) sum += vec4(environment(l.x * t + l.y * b + l.z * r) * l.z, l.z);
  }
  return sum;
}

// The engines' base lobe, preintegrated: Schlick's curve of F0_IN_COAT for the metal under the
// coat (lobes: the ComparisonLobes texel at the base's roughness), tinted, through the same
// layering as ours (matc_coated_base_{{name}}) with our coat.
vec3 engine_base(vec4 lobes, vec4 coat_bbar, float NdotV) {
  vec3 v = (F0_IN_COAT * lobes.x + (vec3(1.0) - F0_IN_COAT) * lobes.y) * matc_coat_tint_{{name}}(NdotV);
  return layered_base(F0 * lobes.x + (vec3(1.0) - F0) * lobes.y, v,
                      dot(matc_coat_coefficients_{{name}}, coat_bbar));
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
  uvec2 pixel = uvec2(gl_FragCoord.xy);
  vec2 shift = vec2(hash(pixel.x + 4096u * pixel.y), hash(pixel.y + 4096u * pixel.x + 17u)) *
               2.3283064365386963e-10;
  float coat_roughness = matc_coat_roughness_{{name}};
  float samples = float(panel.sample_count);
  if (panel.method == 0) {
    result = vec4(sample_lobe(n, v, panel.roughness, true, true, shift) +
                  sample_lobe(n, v, coat_roughness, false, true, shift), samples);
  } else if (panel.method == 1 || panel.method == 2) {
    result = prefiltered_radiance(n, v, panel.method == 1 ? panel.roughness : coat_roughness, shift);
  } else if (panel.method >= 3 && panel.method <= 5) {
    float roughness = panel.method == 4 ? coat_roughness : panel.roughness;
    result = vec4(sample_lobe(n, v, roughness, true, false, shift), samples);
  } else {
    vec4 bbar = textureLod(sampler2D(matc_lut, matc_lut_sampler),
                           matc_lut_texcoord(n.z, panel.roughness), 0.0);
    vec4 coat_bbar = textureLod(sampler2D(matc_lut, matc_lut_sampler),
                                matc_lut_texcoord(n.z, coat_roughness), 0.0);
    vec3 sum;
    if (panel.method == 6) {
      sum = matc_fresnel_preintegrated_{{name}}(bbar, coat_bbar, n.z);
    } else if (panel.method == 7) {
      sum = vec3(matc_coat_fresnel_preintegrated_{{name}}(coat_bbar));
    } else if (panel.method == 9) {
      sum = matc_coat_tint_{{name}}(n.z);
    } else if (panel.method == 10 || panel.method == 11) {
      float weight = matc_coat_weight_{{name}};
      vec4 coat_lobes = textureLod(sampler2D(lobe_lut, matc_lut_sampler),
                                   matc_lut_texcoord(n.z, coat_roughness), 0.0);
      if (panel.method == 10) {
        vec4 lobes = textureLod(sampler2D(lobe_lut, matc_lut_sampler),
                                matc_lut_texcoord(n.z, panel.roughness), 0.0);
        float m = 1.0 - n.z;
        float coat_at_ndotv = 0.04 + 0.96 * (m * m) * (m * m) * m;
        sum = (F0 * lobes.x + (vec3(1.0) - F0) * lobes.y) * (1.0 - weight * coat_at_ndotv);
      } else {
        sum = vec3(weight * (0.04 * coat_lobes.x + 0.96 * coat_lobes.y));
      }
    } else {
      vec4 lobes = textureLod(sampler2D(lobe_lut, matc_lut_sampler),
                              matc_lut_texcoord(n.z, panel.roughness), 0.0);
      sum = engine_base(lobes, coat_bbar, n.z);
    }
    result = vec4(sum, 1.0);
  }
}
