#version 450
// matc {{version}}: the full-screen pass of the cost benchmarks (bench/fullscreen_cost.cpp times it
// on a Vulkan device, bench/gpu_cost.cpp reads its instruction cost on AMD's ISA). Every variant
// of a quantity does the same work around the Fresnel and writes the same target; only the
// Fresnel differs: {{variant}}.
// Bindings (set 0): 0 the preintegrated table, 1 the sampler, 2 the coefficient table (its .xy),
// 3 the LTC table, 4-6 material maps: Schlick's textured F0 at 4; the coefficient table's
// reflectivity and edge tint at 4 and 5; baked coefficient textures F0, C2, C3 at 4, 5, 6;
// 7 the prefiltered environment of the image-light pass (an octahedral map). Coated variants
// (MATC_COST_COAT 1 ours coated, 2 ours bare under a Schlick coat lobe, 3 Filament's clear coat)
// shade two lobes, the coat's at its own roughness, in the GGX-light and image-light passes.
// Filmed variants (MATC_COST_FILM 1 ours from the film's table at binding 8, 2 the film's Airy
// sum over a dielectric base of index from F0, as glTF engines shade KHR_materials_iridescence;
// with a thickness per pixel, 3 ours from the film's stack at binding 8 and 4 that Airy sum, both
// at a thickness coordinate of uv.x, as a thickness texture gives it) run in the GGX-light and
// image-light passes.
{{defines}}
{{library}}
{{material}}
layout(set = 0, binding = 0) uniform texture2D matc_lut;
layout(set = 0, binding = 1) uniform sampler matc_lut_sampler;
#if MATC_COST_TABLE || MATC_COST_F0_TABLE
layout(set = 0, binding = 2) uniform texture2D matc_coefficient_table;
#endif
#if MATC_COST_QUAD_LIGHT || MATC_COST_QUAD_LIGHT_FOLLOWING
layout(set = 0, binding = 3) uniform texture2D matc_ltc;
#endif
#if MATC_COST_MAPS >= 1
layout(set = 0, binding = 4) uniform texture2D map_a;
#endif
#if MATC_COST_MAPS >= 2
layout(set = 0, binding = 5) uniform texture2D map_b;
#endif
#if MATC_COST_MAPS >= 3
layout(set = 0, binding = 6) uniform texture2D map_c;
#endif
#if MATC_COST_IMAGE_LIGHT
layout(set = 0, binding = 7) uniform texture2D environment;
#endif
#if MATC_COST_FILM == 1 || MATC_COST_FILM == 3
layout(set = 0, binding = 8) uniform texture2D film_table;
#endif
layout(location = 0) out vec4 colour;

const float PI = 3.14159265358979;

// Schlick's F as engines write it: (1 - mu)^5 by multiplications (Filament's pow5).
vec3 matc_cost_schlick(vec3 f0, float mu) {
  float m = 1.0 - mu;
  float m2 = m * m;
  return f0 + (vec3(1.0) - f0) * (m2 * m2 * m);
}

#if MATC_COST_FILM == 2 || MATC_COST_FILM == 4
// Belcour and Barla (2017), "A Practical Extension to Microfacet Theory for the Modeling of
// Varying Iridescence", as glTF's KHR_materials_iridescence is shaded by engines (the Khronos
// sample viewer's evalIridescence): air, a film of index n_f and thickness d, and a dielectric
// base of index (1 + sqrt(F0)) / (1 - sqrt(F0)) per channel, Schlick's curve at each interface,
// the first two orders of the Airy sum in Fourier space against Gaussian fits of the CIE
// matching functions. Written here from the paper, for its cost.
vec3 matc_cost_film_sensitivity(float path_difference_nm, vec3 shift) {
  float phase = 6.28318530718 * path_difference_nm * 1e-9;
  const vec3 amplitude = vec3(5.4856e-13, 4.4201e-13, 5.2481e-13);
  const vec3 position = vec3(1.6810e+06, 1.7953e+06, 2.2084e+06);
  const vec3 variance = vec3(4.3278e+09, 9.3046e+09, 6.6121e+09);
  vec3 xyz = amplitude * sqrt(6.28318530718 * variance) * cos(position * phase + shift) *
             exp(-phase * phase * variance);
  xyz.x += 9.7470e-14 * sqrt(6.28318530718 * 4.5282e+09) * cos(2.2399e+06 * phase + shift.x) *
           exp(-4.5282e+09 * phase * phase);
  xyz /= 1.0685e-7;
  const mat3 xyz_to_rec709 = mat3(3.2404542, -0.9692660, 0.0556434, -1.5371385, 1.8760108,
                                  -0.2040259, -0.4985314, 0.0415560, 1.0572252);
  return xyz_to_rec709 * xyz;
}

vec3 matc_cost_film_over_dielectric(vec3 f0, float cos_theta1, float thickness) {
  const float film_ior_given = {{film_ior}};
  // The film's index fades to air's below 30 nm, as the engines do.
  float film_ior = mix(1.0, film_ior_given, smoothstep(0.0, 30.0, thickness));
  float sin_theta2_sq = (1.0 - cos_theta1 * cos_theta1) / (film_ior * film_ior);
  float cos_theta2_sq = 1.0 - sin_theta2_sq;
  if (cos_theta2_sq < 0.0) return vec3(1.0);
  float cos_theta2 = sqrt(cos_theta2_sq);
  float r0 = (film_ior - 1.0) / (film_ior + 1.0);
  float r12 = matc_cost_schlick(vec3(r0 * r0), cos_theta1).x;
  float t121 = 1.0 - r12;
  float phi12 = film_ior < 1.0 ? 3.14159265359 : 0.0;
  float phi21 = 3.14159265359 - phi12;
  vec3 sqrt_f0 = sqrt(clamp(f0, 0.0, 0.9999));
  vec3 base_ior = (1.0 + sqrt_f0) / (1.0 - sqrt_f0);
  vec3 r1 = (base_ior - film_ior) / (base_ior + film_ior);
  vec3 r23 = matc_cost_schlick(r1 * r1, cos_theta2);
  vec3 phi23 = mix(vec3(0.0), vec3(3.14159265359), lessThan(base_ior, vec3(film_ior)));
  float path_difference = 2.0 * film_ior * thickness * cos_theta2;
  vec3 phi = vec3(phi21) + phi23;
  vec3 r123_sq = clamp(r12 * r23, 1e-5, 0.9999);
  vec3 r123 = sqrt(r123_sq);
  vec3 rs = t121 * t121 * r23 / (vec3(1.0) - r123_sq);
  vec3 intensity = vec3(r12) + rs;
  vec3 cm = rs - t121;
  for (int m = 1; m <= 2; ++m) {
    cm *= r123;
    intensity += cm * 2.0 * matc_cost_film_sensitivity(float(m) * path_difference, float(m) * phi);
  }
  return max(intensity, vec3(0.0));
}
#endif

void main() {
  // Every pixel a different (NdotV, roughness), like the pixels of a shaded object.
  vec2 uv = gl_FragCoord.xy / vec2({{width}}.0, {{height}}.0);
#if MATC_COST_MAPS >= 1
  // A textured metal: its maps read at a texture coordinate of its own.
  vec2 map_uv = uv * vec2(3.1, 5.3);
  vec3 a = textureLod(sampler2D(map_a, matc_lut_sampler), map_uv, 0.0).xyz;
#endif
#if MATC_COST_MAPS >= 2
  vec3 b = textureLod(sampler2D(map_b, matc_lut_sampler), map_uv, 0.0).xyz;
#endif
#if MATC_COST_MAPS >= 3
  vec3 c3 = textureLod(sampler2D(map_c, matc_lut_sampler), map_uv, 0.0).xyz;
#endif
#if MATC_COST_METAL_ROUGH
  // glTF's metal-rough model: the base colour is map a, the metalness map b's blue channel.
  float metalness = b.z;
#endif
#if MATC_COST_SCHLICK
#if MATC_COST_METAL_ROUGH
  // As engines shade it: one Schlick curve, F0 blended from the dielectric's to the base colour.
  vec3 F0 = mix(vec3(0.04), a, metalness);
#elif MATC_COST_MAPS
  vec3 F0 = a;
#elif MATC_COST_COAT == 3
  // Filament's f0ClearCoatToSurface: F0 seen from inside a coat of 1.5, a fit of the exact
  // conversion.
  const vec3 f0_air = vec3({{f0}});
  vec3 F0 = clamp(f0_air * (f0_air * (0.941892 - 0.263008 * f0_air) + 0.346479) - 0.0285998,
                  0.0, 1.0);
#else
  const vec3 F0 = vec3({{f0}});
#endif
#elif MATC_COST_TABLE
  MatcFresnelCoefficients c =
      MATC_COEFFICIENTS_FROM_TABLE(sampler2D(matc_coefficient_table, matc_lut_sampler), a, b);
#elif MATC_COST_BAKED
  MatcFresnelCoefficients c = matc_coefficients_from_baked(a, b, c3);
#elif MATC_COST_FROM_F0
  // The material's rows stand in for a glTF metal's at F0 = 0 (the same instructions).
  MatcFresnelCoefficients c = matc_coefficients_from_f0(matc_coefficients_{{name}}, a);
#elif MATC_COST_F0_TABLE
  // The coefficient table's binding stands in for the F0 table (the same fetch instructions).
  MatcFresnelCoefficients c =
      MATC_COEFFICIENTS_FROM_F0_TABLE(sampler2D(matc_coefficient_table, matc_lut_sampler), a);
#if MATC_COST_COAT == 1
  // Under a coat, the metal seen from the coat too (the table's rows 3 to 5).
  MatcFresnelCoefficients under_coat =
      MATC_UNDER_COAT_FROM_F0_TABLE(sampler2D(matc_coefficient_table, matc_lut_sampler), a);
#endif
#else
  MatcFresnelCoefficients c = matc_coefficients_{{name}};
#endif
// F at mu = V.H and Fbar from a texel of the model's table, for each model.
#if MATC_COST_SCHLICK
#define COST_FRESNEL(MU) matc_cost_schlick(F0, (MU))
#define COST_FRESNEL_PREINTEGRATED(TEXEL) (F0 * (TEXEL).x + (vec3(1.0) - F0) * (TEXEL).y)
#elif MATC_COST_METAL_ROUGH
// Ours mixed with the dielectric's Schlick curve by metalness (matc_metal_rough); for image light
// the dielectric's split sum from the engine's own two-channel DFG table (matc_lut's binding
// stands in for it: the same fetch instructions, at the engine's (roughness, NdotV) coordinates).
#define COST_FRESNEL(MU) \
  matc_metal_rough(matc_dielectric_fresnel(vec3(0.04), vec3(1.0), (MU)), matc_fresnel(c, (MU)), metalness)
#define COST_ENGINE_DFG textureLod(sampler2D(matc_lut, matc_lut_sampler), vec2(uv.y, uv.x), 0.0)
#define COST_FRESNEL_PREINTEGRATED(TEXEL)                                                      \
  matc_metal_rough(vec3(0.04) * COST_ENGINE_DFG.x + vec3(0.96) * COST_ENGINE_DFG.y,           \
                   matc_fresnel_preintegrated(c, (TEXEL)), metalness)
#elif MATC_COST_FILM == 1
// A filmed metal: F and Fbar from its own table (image light at the pass' NdotV and roughness).
#define COST_FRESNEL(MU) \
  matc_fresnel_{{name}}(MATC_FILM_FRESNEL(sampler2D(film_table, matc_lut_sampler), (MU)))
#define COST_FRESNEL_PREINTEGRATED(TEXEL) \
  matc_fresnel_preintegrated_{{name}}(     \
      MATC_FILM_PREINTEGRATED(sampler2D(film_table, matc_lut_sampler), NoV, uv.y))
#elif MATC_COST_FILM == 3
// A thickness per pixel: F and Fbar from the film's stack at the pixel's thickness coordinate.
#define COST_FRESNEL(MU)                                                                     \
  matc_fresnel_{{name}}(MATC_FILM_STACK_FRESNEL(sampler2D(film_table, matc_lut_sampler), (MU), \
                                                uv.x, matc_film_slices_{{name}}))
#define COST_FRESNEL_PREINTEGRATED(TEXEL)                                                  \
  matc_fresnel_preintegrated_{{name}}(MATC_FILM_STACK_PREINTEGRATED(                       \
      sampler2D(film_table, matc_lut_sampler),                                             \
      matc_film_stack_preintegrated_texcoords(NoV, uv.y, uv.x, matc_film_slices_{{name}})))
#elif MATC_COST_FILM == 2 || MATC_COST_FILM == 4
// The engines' iridescence: Schlick's curve mixed with the film's by the film's coverage; for
// image light the film's F at NdotV in place of F0 in Schlick's split sum. With a thickness per
// pixel (4), the thickness is the texture's mix of the range at uv.x.
#define COST_FILM_F0 vec3({{f0}})
#if MATC_COST_FILM == 4
#define COST_FILM_THICKNESS mix({{film_minimum}}, {{film_thickness}}, uv.x)
#else
#define COST_FILM_THICKNESS {{film_thickness}}
#endif
#define COST_FRESNEL(MU)                                             \
  mix(matc_cost_schlick(COST_FILM_F0, (MU)),                         \
      matc_cost_film_over_dielectric(COST_FILM_F0, (MU), COST_FILM_THICKNESS), {{film_weight}})
#define COST_FRESNEL_PREINTEGRATED(TEXEL)                                                       \
  (mix(COST_FILM_F0, matc_cost_film_over_dielectric(COST_FILM_F0, NoV, COST_FILM_THICKNESS),  \
       {{film_weight}}) *                                                                      \
       (TEXEL).x +                                                                             \
   (vec3(1.0) - mix(COST_FILM_F0,                                                              \
                    matc_cost_film_over_dielectric(COST_FILM_F0, NoV, COST_FILM_THICKNESS),    \
                    {{film_weight}})) *                                                        \
       (TEXEL).y)
#elif MATC_COST_TABLE || MATC_COST_BAKED || MATC_COST_FROM_F0 || MATC_COST_F0_TABLE
#define COST_FRESNEL(MU) matc_fresnel(c, (MU))
#define COST_FRESNEL_PREINTEGRATED(TEXEL) matc_fresnel_preintegrated(c, (TEXEL))
#else
// A compiled material: its own functions, as an engine calls them (no clamp at 0 where matc
// proved its curve non-negative).
#define COST_FRESNEL(MU) matc_fresnel_{{name}}((MU))
#define COST_FRESNEL_PREINTEGRATED(TEXEL) matc_fresnel_preintegrated_{{name}}((TEXEL))
#endif

#if MATC_COST_DIRECT
  // F alone, per light.
  vec3 f = COST_FRESNEL(uv.x) * uv.y;
#elif MATC_COST_GGX_LIGHT
  // One punctual light, as engines shade it: GGX D, height-correlated Smith V, F, NdotL.
  vec3 N = normalize(vec3(uv.x - 0.5, 0.6, uv.y - 0.5));
  vec3 V = normalize(vec3(0.3 - uv.y, 1.0, 0.2));
  vec3 L = normalize(vec3(-0.4, 0.8, 0.3));
  vec3 H = normalize(V + L);
  float NoV = max(dot(N, V), 1e-4);
  float NoL = clamp(dot(N, L), 0.0, 1.0);
  float NoH = clamp(dot(N, H), 0.0, 1.0);
  float VoH = clamp(dot(V, H), 0.0, 1.0);
  float alpha = uv.y * uv.y;
  float a2 = alpha * alpha;
  float d = (NoH * a2 - NoH) * NoH + 1.0;
  float D = a2 / (PI * d * d);
  float Vis = 0.5 / (NoL * sqrt(NoV * NoV * (1.0 - a2) + a2) + NoV * sqrt(NoL * NoL * (1.0 - a2) + a2));
#if MATC_COST_COAT
  // The coat lobe: the same GGX D and Smith V at the coat's roughness.
  float coat_alpha = {{coat_roughness}} * {{coat_roughness}};
  float coat_a2 = coat_alpha * coat_alpha;
  float coat_d = (NoH * coat_a2 - NoH) * NoH + 1.0;
  float coat_D = coat_a2 / (PI * coat_d * coat_d);
  float coat_Vis = 0.5 / (NoL * sqrt(NoV * NoV * (1.0 - coat_a2) + coat_a2) +
                          NoV * sqrt(NoL * NoL * (1.0 - coat_a2) + coat_a2));
#if MATC_COST_COAT == 1 && MATC_COST_F0_TABLE && MATC_COST_METAL_ROUGH
  // glTF's metal-rough model under the coat: the dielectric through the coat's transmission.
  vec3 base_f = matc_metal_rough_{{name}}(matc_dielectric_fresnel(vec3(0.04), vec3(1.0), VoH),
                                          matc_fresnel_textured_{{name}}(c, under_coat, VoH),
                                          metalness, NoV);
  float coat_f = matc_coat_fresnel_{{name}}(VoH);
#elif MATC_COST_COAT == 1 && MATC_COST_F0_TABLE
  vec3 base_f = matc_fresnel_textured_{{name}}(c, under_coat, VoH);
  float coat_f = matc_coat_fresnel_{{name}}(VoH);
#elif MATC_COST_COAT == 1 && MATC_COST_FILM == 1
  // A filmed metal under the coat: its table's texel is the base lobe.
  vec3 base_f = COST_FRESNEL(VoH);
  float coat_f = matc_coat_fresnel_{{name}}(VoH);
#elif MATC_COST_COAT == 1
  vec3 base_f = matc_fresnel_{{name}}(VoH);
  float coat_f = matc_coat_fresnel_{{name}}(VoH);
#else
  float coat_f = {{coat_weight}} * matc_cost_schlick(vec3(0.04), VoH).x;
  vec3 base_f = COST_FRESNEL(VoH) * (1.0 - coat_f);
#endif
  vec3 f = (base_f * (D * Vis) + coat_f * (coat_D * coat_Vis)) * NoL;
#else
  vec3 f = COST_FRESNEL(VoH) * (D * Vis * NoL);
#endif
#elif MATC_COST_QUAD_LIGHT || MATC_COST_QUAD_LIGHT_FOLLOWING
  // A quad light over a field of normals: each pixel its own N (so its own NdotV), P and the
  // roughness uv.y; the LTC integral is the same code in every variant, only the Fresnel differs
  // (with ours, the quality level's shape and Fresnel that follow the light in the _FOLLOWING
  // pass).
  vec3 N = normalize(vec3(uv.x - 0.5, 0.6, uv.y - 0.5));
  vec3 V = vec3(0.0, 1.0, 0.0);
  vec3 P = vec3(2.0 * uv.x - 1.0, 0.0, 2.0 * uv.y - 1.0);
  float NoV = dot(N, V);
  vec4 texel = textureLod(sampler2D(matc_lut, matc_lut_sampler), {{lut_texcoord}}(NoV, uv.y), 0.0);
  vec4 ltc = textureLod(sampler2D(matc_ltc, matc_lut_sampler), matc_ltc_texcoord(NoV, uv.y), 0.0);
  vec3 q0 = vec3(-1.0, 2.0, -1.5), q1 = vec3(1.0, 2.0, -1.5);
  vec3 q2 = vec3(1.0, 2.5, -0.5), q3 = vec3(-1.0, 2.5, -0.5);
  MatcLtcPolygon polygon = matc_ltc_quad_polygon(matc_ltc_transform(N, V, ltc), P, q0, q1, q2, q3);
#if MATC_COST_QUAD_LIGHT_FOLLOWING && !MATC_COST_SCHLICK
  vec3 geometry = matc_ltc_following_geometry(polygon, ltc, NoV, uv.y, texel.x);
  vec3 f = matc_ltc_following_radiance(geometry, texel, COST_FRESNEL(geometry.y),
                                       COST_FRESNEL_PREINTEGRATED(texel));
#else
  vec3 f = matc_ltc_polygon_result(polygon) * COST_FRESNEL_PREINTEGRATED(texel);
#endif
#elif MATC_COST_CLOSED_FORM
  // Fbar without a texture: the closed form of our table, or Karis' analytic fit of Schlick's
  // split sum ("Physically Based Shading on Mobile", 2014) with the same roughness.
#if MATC_COST_SCHLICK
  vec4 r4 = uv.y * vec4(-1.0, -0.0275, -0.572, 0.022) + vec4(1.0, 0.0425, 1.04, -0.04);
  float a004 = min(r4.x * r4.x, exp2(-9.28 * uv.x)) * r4.x + r4.y;
  vec2 ab = vec2(-1.04, 1.04) * a004 + r4.zw;
  vec3 f = F0 * ab.x + ab.y;
#else
  vec3 f = COST_FRESNEL_PREINTEGRATED(matc_preintegrated_basis_analytic(uv.x, uv.y));
#endif
#else
  // Image-based light as engines shade it with the split sum: the prefiltered environment along
  // the reflected view (an octahedral map, its mip chosen by roughness) times Fbar from one fetch
  // of the table (for Schlick's, the table baked from ComparisonLobes: x = albedo, y = Schlick's
  // lobe). Only Fbar differs between the variants.
  vec3 N = normalize(vec3(uv.x - 0.5, 0.6, uv.y - 0.5));
  vec3 V = normalize(vec3(0.3 - uv.y, 1.0, 0.2));
  float NoV = max(dot(N, V), 1e-4);
  vec3 R = reflect(-V, N);
  vec3 o = R / (abs(R.x) + abs(R.y) + abs(R.z));
  vec2 env_uv = (o.y >= 0.0 ? o.xz : (1.0 - abs(o.zx)) * sign(o.xz)) * 0.5 + 0.5;
  vec3 radiance = textureLod(sampler2D(environment, matc_lut_sampler), env_uv, uv.y * 6.0).rgb;
  vec4 texel = textureLod(sampler2D(matc_lut, matc_lut_sampler), {{lut_texcoord}}(NoV, uv.y), 0.0);
#if MATC_COST_COAT
  // The coat lobe: the environment and the table again, at the coat's roughness.
  vec3 coat_radiance =
      textureLod(sampler2D(environment, matc_lut_sampler), env_uv, {{coat_roughness}} * 6.0).rgb;
  vec4 coat_texel = textureLod(sampler2D(matc_lut, matc_lut_sampler),
                               matc_lut_texcoord(NoV, {{coat_roughness}}), 0.0);
#if MATC_COST_COAT == 1 && MATC_COST_F0_TABLE && MATC_COST_METAL_ROUGH
  vec3 f = matc_metal_rough_{{name}}(vec3(0.04) * COST_ENGINE_DFG.x + vec3(0.96) * COST_ENGINE_DFG.y,
                                     matc_fresnel_preintegrated_textured_{{name}}(
                                         c, under_coat, texel, coat_texel, NoV),
                                     metalness, NoV) *
               radiance +
           matc_coat_fresnel_preintegrated_{{name}}(coat_texel) * coat_radiance;
#elif MATC_COST_COAT == 1 && MATC_COST_F0_TABLE
  vec3 f = matc_fresnel_preintegrated_textured_{{name}}(c, under_coat, texel, coat_texel, NoV) *
               radiance +
           matc_coat_fresnel_preintegrated_{{name}}(coat_texel) * coat_radiance;
#elif MATC_COST_COAT == 1 && MATC_COST_FILM == 1
  vec3 f = COST_FRESNEL_PREINTEGRATED(texel) * radiance +
           matc_coat_fresnel_preintegrated_{{name}}(coat_texel) * coat_radiance;
#elif MATC_COST_COAT == 1
  vec3 f = matc_fresnel_preintegrated_{{name}}(texel, coat_texel, NoV) * radiance +
           matc_coat_fresnel_preintegrated_{{name}}(coat_texel) * coat_radiance;
#else
  float coat_f = {{coat_weight}} * (0.04 * coat_texel.x + 0.96 * coat_texel.y);
  vec3 f = COST_FRESNEL_PREINTEGRATED(texel) * (1.0 - coat_f) * radiance + coat_f * coat_radiance;
#endif
#else
  vec3 f = COST_FRESNEL_PREINTEGRATED(texel) * radiance;
#endif
#endif
  colour = vec4(f, 1.0);
}
