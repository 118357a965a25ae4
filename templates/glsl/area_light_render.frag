#version 450
// matc {{version}}: one panel of the area-light renders (examples/render) for material {{name}}: a
// sphere on a ground plane under a two-sided rectangular light, GGX with roughness from the push
// constants, no shadowing (the integral LTC approximates). Each method writes one estimate:
//   0: the Monte-Carlo reference, exact Fresnel: light-area and visible-normal samples combined
//      by the balance heuristic
//   1: the exact lobe's integral over the light (no Fresnel) times Fbar / E of the exact curve:
//      the split L = shape x preintegrated Fresnel without LTC's shape error
//   2: I_ltc times the exact preintegrated Fresnel (visible-normal sampling): LTC's own error
//   3: I_ltc times Schlick's preintegrated Fresnel (the ComparisonLobes table)
//   4: ours, matc_ltc_quad_light with matc_coefficients_{{name}}
//   5: ours at the quality level, matc_ltc_quad_light_following (shape and Fresnel following
//      the light)
// A filmed metal (MATC_RENDER_FILM 1) reads its own table at binding 5: I_ltc times its Fbar for 4,
// and the same for 5 (the quality level follows the 4-term basis; docs/thin-film.md).
// Each pass writes (sum, weight) for its share of the samples; the host adds passes up and
// divides. Background pixels write a negative weight.
{{film}}
{{library}}
{{material}}
layout(set = 0, binding = 0) uniform texture2D matc_lut;
layout(set = 0, binding = 1) uniform texture2D lobe_lut;  // ComparisonLobes: x albedo, y Schlick
layout(set = 0, binding = 2) uniform sampler matc_lut_sampler;
layout(std430, set = 0, binding = 3) readonly buffer ExactCurve { vec4 exact_curve[]; };
layout(set = 0, binding = 4) uniform texture2D matc_ltc;
#if MATC_RENDER_FILM
layout(set = 0, binding = 5) uniform texture2D film_table;
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

// The scene (y up): a sphere resting on the plane y = 0, the light above and behind it, facing
// down towards the camera (drawn white where the camera sees it; not part of the statistics).
const vec3 CAMERA = vec3(0.0, 0.9, 3.6);
const vec3 TARGET = vec3(0.0, 0.55, 0.0);
const float TAN_HALF_FOV = 0.45;
const vec3 SPHERE_CENTRE = vec3(0.0, 0.6, 0.0);
const float SPHERE_RADIUS = 0.6;
const vec3 LIGHT_CENTRE = vec3(0.0, 1.9, -1.4);
const vec3 LIGHT_RIGHT = vec3(1.2, 0.0, 0.0);    // half-extent along x
const vec3 LIGHT_UP = vec3(0.0, 0.2, 0.28);      // half-extent, tilted down towards the camera
const float LIGHT_RADIANCE = 4.0;

{{render_sampling}}

vec3 exact_fresnel(float mu) {
  float x = clamp(mu, 0.0, 1.0) * float(CURVE_SIZE - 1u);
  uint i = min(uint(x), CURVE_SIZE - 2u);
  return mix(exact_curve[i].rgb, exact_curve[i + 1u].rgb, x - float(i));
}

// The camera ray's first hit: the sphere, or the plane within |x| < 3, -2.5 < z < 3.
bool trace(vec3 origin, vec3 direction, out vec3 position, out vec3 normal) {
  vec3 oc = origin - SPHERE_CENTRE;
  float b = dot(oc, direction);
  float c = dot(oc, oc) - SPHERE_RADIUS * SPHERE_RADIUS;
  float discriminant = b * b - c;
  if (discriminant > 0.0) {
    float t = -b - sqrt(discriminant);
    if (t > 0.0) {
      position = origin + t * direction;
      normal = normalize(position - SPHERE_CENTRE);
      return true;
    }
  }
  if (direction.y < 0.0) {
    float t = -origin.y / direction.y;
    position = origin + t * direction;
    normal = vec3(0.0, 1.0, 0.0);
    return abs(position.x) < 3.0 && position.z > -2.5 && position.z < 3.0;
  }
  return false;
}

// GGX in the shading frame (normal +z): f cos(L) without Fresnel, and the density of
// visible-normal sampling, at a light direction l for the view v.
vec2 lobe(vec3 v, vec3 l, float alpha) {
  if (l.z <= 0.0) return vec2(0.0);
  vec3 h = normalize(v + l);
  float a2 = alpha * alpha;
  float d = h.z * h.z * (a2 - 1.0) + 1.0;
  float distribution = a2 / (PI * d * d);
  float lambda_v = smith_lambda(v.z, alpha);
  float g2 = 1.0 / (1.0 + lambda_v + smith_lambda(l.z, alpha));
  float g1 = 1.0 / (1.0 + lambda_v);
  return vec2(distribution * g2, distribution * g1) / (4.0 * v.z);
}

// The light's density over solid angle towards world direction l at distance t.
float light_pdf(vec3 l, float t) {
  vec3 normal = cross(LIGHT_RIGHT, LIGHT_UP);
  float area = 4.0 * length(normal);
  return t * t / (area * abs(dot(normalize(normal), l)));
}

// Where a ray from p along unit d meets the light, or 0.
float light_hit(vec3 p, vec3 d) {
  vec3 normal = normalize(cross(LIGHT_RIGHT, LIGHT_UP));
  float along = dot(normal, d);
  if (abs(along) < 1e-8) return 0.0;
  float t = dot(normal, LIGHT_CENTRE - p) / along;
  if (t <= 0.0) return 0.0;
  vec3 q = p + t * d - LIGHT_CENTRE;
  // LIGHT_RIGHT and LIGHT_UP are orthogonal.
  float s = dot(q, LIGHT_RIGHT) / dot(LIGHT_RIGHT, LIGHT_RIGHT);
  float u = dot(q, LIGHT_UP) / dot(LIGHT_UP, LIGHT_UP);
  return abs(s) <= 1.0 && abs(u) <= 1.0 ? t : 0.0;
}

// One pair of the reference's samples for the Hammersley point u: a point of the light's area (a
// second point set, rotated by a fixed offset) and a visible normal, each weighted by the balance
// heuristic; adds f cos / (p_light + p_lobe) with the exact Fresnel to `with_fresnel` and without
// it to `lobe_only`. Shading frame (t, b, N), view in it.
void add_light_samples(vec3 P, vec3 t, vec3 b, vec3 N, vec3 view, float alpha, vec2 u,
                       inout vec3 with_fresnel, inout float lobe_only) {
  vec2 w = fract(u + vec2(0.5, 0.25));
  vec3 y = LIGHT_CENTRE + (2.0 * w.x - 1.0) * LIGHT_RIGHT + (2.0 * w.y - 1.0) * LIGHT_UP;
  float distance = length(y - P);
  vec3 l_world = (y - P) / distance;
  vec3 l = vec3(dot(l_world, t), dot(l_world, b), dot(l_world, N));
  vec2 value = lobe(view, l, alpha);
  if (value.x > 0.0) {
    float share = value.x / (light_pdf(l_world, distance) + value.y);
    with_fresnel += share * exact_fresnel(dot(view, normalize(view + l)));
    lobe_only += share;
  }
  vec3 h = sample_visible_normal(view, alpha, u);
  l = reflect(-view, h);
  l_world = l.x * t + l.y * b + l.z * N;
  float hit = light_hit(P, l_world);
  if (l.z > 0.0 && hit > 0.0) {
    value = lobe(view, l, alpha);
    float share = value.x / (light_pdf(l_world, hit) + value.y);
    with_fresnel += share * exact_fresnel(dot(view, h));
    lobe_only += share;
  }
}

// One visible-normal sample of the split sum: adds scale F(V.H) G2/G1 to `fresnel_sum` and G2/G1
// to `albedo_sum` (nothing below the horizon), with height-correlated Smith as the table is baked.
void add_split_sum_sample(vec3 view, float alpha, float lambda_v, vec2 u, float scale,
                          inout vec3 fresnel_sum, inout float albedo_sum) {
  vec3 h = sample_visible_normal(view, alpha, u);
  vec3 l = reflect(-view, h);
  if (l.z > 0.0) {
    float g2_over_g1 = (1.0 + lambda_v) / (1.0 + lambda_v + smith_lambda(l.z, alpha));
    fresnel_sum += scale * exact_fresnel(dot(view, h)) * g2_over_g1;
    albedo_sum += g2_over_g1;
  }
}

void main() {
  vec2 ndc = (gl_FragCoord.xy / SIZE * 2.0 - 1.0) * vec2(1.0, -1.0);
  vec3 forward = normalize(TARGET - CAMERA);
  vec3 right = normalize(cross(forward, vec3(0.0, 1.0, 0.0)));
  vec3 up = cross(right, forward);
  vec3 direction =
      normalize(forward + TAN_HALF_FOV * (ndc.x * SIZE.x / SIZE.y * right + ndc.y * up));
  vec3 P, N;
  bool hit = trace(CAMERA, direction, P, N);
  float light = light_hit(CAMERA, direction);
  if (light > 0.0 && (!hit || light < length(P - CAMERA))) {
    result = vec4(-1.0, -1.0, -1.0, -1.0);
    return;
  }
  if (!hit) {
    result = vec4(-0.02, -0.02, -0.025, -1.0);
    return;
  }
  vec3 V = -direction;
  // Back-facing normals of the sphere's silhouette: keep NdotV just above zero.
  if (dot(N, V) < 1e-4) V = normalize(V + N * (1e-4 - dot(N, V)));
  float alpha = max(panel.roughness * panel.roughness, 1e-4);
  vec3 q0 = LIGHT_CENTRE - LIGHT_RIGHT - LIGHT_UP;
  vec3 q1 = LIGHT_CENTRE + LIGHT_RIGHT - LIGHT_UP;
  vec3 q2 = LIGHT_CENTRE + LIGHT_RIGHT + LIGHT_UP;
  vec3 q3 = LIGHT_CENTRE - LIGHT_RIGHT + LIGHT_UP;
  float ndotv = dot(N, V);
  vec4 bbar = textureLod(sampler2D(matc_lut, matc_lut_sampler),
                         matc_lut_texcoord(ndotv, panel.roughness), 0.0);
  vec4 ltc = textureLod(sampler2D(matc_ltc, matc_lut_sampler),
                        matc_ltc_texcoord(ndotv, panel.roughness), 0.0);
  float integral = matc_ltc_quad_integral(matc_ltc_transform(N, V, ltc), P, q0, q1, q2, q3);

  uvec2 pixel = uvec2(gl_FragCoord.xy);
  vec2 shift = vec2(hash(pixel.x + 4096u * pixel.y), hash(pixel.y + 4096u * pixel.x + 17u)) *
               2.3283064365386963e-10;
  vec3 t, b;
  frame(N, t, b);
  vec3 view = vec3(dot(V, t), dot(V, b), dot(V, N));
  vec3 sum = vec3(0.0);
  float weight = 1.0;
  uint last = panel.first_sample + panel.sample_count;
  float lambda_v = smith_lambda(view.z, alpha);
  if (panel.method == 0) {
    float unused = 0.0;
    for (uint i = panel.first_sample; i < last; ++i)
      add_light_samples(P, t, b, N, view, alpha, sample_point(i, panel.total_samples, shift), sum,
                        unused);
    weight = float(panel.sample_count);
  } else if (panel.method == 1) {
    // Fbar / E from a fixed set of 256 visible normals (the same in every pass).
    vec3 fresnel_sum = vec3(0.0);
    float albedo_sum = 0.0;
    for (uint i = 0u; i < 256u; ++i)
      add_split_sum_sample(view, alpha, lambda_v, sample_point(i, 256u, shift), 1.0, fresnel_sum,
                           albedo_sum);
    vec3 average_fresnel = fresnel_sum / max(albedo_sum, 1e-8);
    vec3 unused = vec3(0.0);
    float lobe_sum = 0.0;
    for (uint i = panel.first_sample; i < last; ++i)
      add_light_samples(P, t, b, N, view, alpha, sample_point(i, panel.total_samples, shift),
                        unused, lobe_sum);
    sum = lobe_sum * average_fresnel;
    weight = float(panel.sample_count);
  } else if (panel.method == 2) {
    float unused = 0.0;
    for (uint i = panel.first_sample; i < last; ++i)
      add_split_sum_sample(view, alpha, lambda_v, sample_point(i, panel.total_samples, shift),
                           integral, sum, unused);
    weight = float(panel.sample_count);
  } else if (panel.method == 3) {
    vec4 lobes = textureLod(sampler2D(lobe_lut, matc_lut_sampler),
                            matc_lut_texcoord(ndotv, panel.roughness), 0.0);
    sum = integral * (F0 * lobes.x + (vec3(1.0) - F0) * lobes.y);
  } else {
#if MATC_RENDER_FILM
    sum = integral * matc_fresnel_preintegrated_{{name}}(MATC_FILM_PREINTEGRATED(
                         sampler2D(film_table, matc_lut_sampler), ndotv, panel.roughness));
#else
    if (panel.method == 4) {
      sum = matc_ltc_quad_light(matc_coefficients_{{name}}, bbar, ltc, N, V, P, q0, q1, q2, q3);
    } else {
      sum = matc_ltc_quad_light_following(matc_coefficients_{{name}}, bbar, ltc, panel.roughness,
                                          N, V, P, q0, q1, q2, q3);
    }
#endif
  }
  result = vec4(LIGHT_RADIANCE * sum, weight);
}
