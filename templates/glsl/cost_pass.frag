#version 450
// matc {{version}}: the full-screen pass of the cost benchmark (bench/fullscreen_cost.cpp). Every
// variant reads the same RGBA32F table once through the same texture coordinates (the closed-form
// quantity reads none) and writes the same target; only the Fresnel differs: {{variant}}. The
// coefficient-table variant also fetches its coefficients, three times, from the table bound at
// binding 2; the quad-light quantity also reads the LTC table at binding 3.
{{defines}}
{{library}}
{{material}}
layout(set = 0, binding = 0) uniform texture2D matc_lut;
layout(set = 0, binding = 1) uniform sampler matc_lut_sampler;
#if MATC_COST_TABLE
layout(set = 0, binding = 2) uniform texture2D matc_coefficient_table;
#endif
#if MATC_COST_QUAD_LIGHT
layout(set = 0, binding = 3) uniform texture2D matc_ltc;
#endif
layout(location = 0) out vec4 colour;

const vec3 F0 = vec3({{f0}});

void main() {
  // Every pixel a different (NdotV, roughness), like the pixels of a shaded object.
  vec2 uv = gl_FragCoord.xy / vec2({{width}}.0, {{height}}.0);
#if MATC_COST_TABLE
  // A textured metal: r and g change from pixel to pixel (a few multiply-adds stand in for the
  // texture reads every model would make for its base colour).
  vec3 r = fract(uv.xyx * vec3(3.1, 5.3, 7.7)) * 0.95;
  vec3 g = fract(uv.yxy * vec3(2.3, 4.1, 6.7));
  MatcFresnelCoefficients c =
      MATC_COEFFICIENTS_FROM_TABLE(sampler2D(matc_coefficient_table, matc_lut_sampler), r, g);
#endif
#if MATC_COST_DIRECT
  float mu = uv.x;
#if MATC_COST_TABLE
  vec3 f = matc_fresnel(c, mu);
#elif MATC_COST_OURS
  vec3 f = matc_fresnel_{{name}}(mu);
#else
  vec3 f = F0 + (vec3(1.0) - F0) * pow(1.0 - mu, 5.0);
#endif
  colour = vec4(f * uv.y, 1.0);
#elif MATC_COST_QUAD_LIGHT
  // A quad light over a field of normals: each pixel its own N (so its own NdotV), P and the
  // roughness uv.y; the LTC integral is the same code in every variant, only the Fresnel differs.
  vec3 N = normalize(vec3(uv.x - 0.5, 0.6, uv.y - 0.5));
  vec3 V = vec3(0.0, 1.0, 0.0);
  vec3 P = vec3(2.0 * uv.x - 1.0, 0.0, 2.0 * uv.y - 1.0);
  float ndotv = dot(N, V);
  vec4 texel = textureLod(sampler2D(matc_lut, matc_lut_sampler), matc_lut_texcoord(ndotv, uv.y), 0.0);
  vec4 ltc = textureLod(sampler2D(matc_ltc, matc_lut_sampler), matc_ltc_texcoord(ndotv, uv.y), 0.0);
  vec3 q0 = vec3(-1.0, 2.0, -1.5), q1 = vec3(1.0, 2.0, -1.5);
  vec3 q2 = vec3(1.0, 2.5, -0.5), q3 = vec3(-1.0, 2.5, -0.5);
#if MATC_COST_TABLE
  vec3 f = matc_ltc_quad_light(c, texel, ltc, N, V, P, q0, q1, q2, q3);
#elif MATC_COST_OURS
  vec3 f = matc_ltc_quad_light(matc_coefficients_{{name}}, texel, ltc, N, V, P, q0, q1, q2, q3);
#else
  float integral = matc_ltc_quad_integral(matc_ltc_transform(N, V, ltc), P, q0, q1, q2, q3);
  vec3 f = integral * (F0 * texel.x + (vec3(1.0) - F0) * texel.y);
#endif
  colour = vec4(f, 1.0);
#elif MATC_COST_CLOSED_FORM
  // Fbar without a texture: the closed form of our table, or Karis' analytic fit of Schlick's
  // split sum ("Physically Based Shading on Mobile", 2014) with the same roughness.
#if MATC_COST_TABLE
  vec3 f = matc_fresnel_preintegrated(c, matc_preintegrated_basis_analytic(uv.x, uv.y));
#elif MATC_COST_OURS
  vec3 f = matc_fresnel_preintegrated_{{name}}(matc_preintegrated_basis_analytic(uv.x, uv.y));
#else
  vec4 r4 = uv.y * vec4(-1.0, -0.0275, -0.572, 0.022) + vec4(1.0, 0.0425, 1.04, -0.04);
  float a004 = min(r4.x * r4.x, exp2(-9.28 * uv.x)) * r4.x + r4.y;
  vec2 ab = vec2(-1.04, 1.04) * a004 + r4.zw;
  vec3 f = F0 * ab.x + ab.y;
#endif
  colour = vec4(f, 1.0);
#else
  vec4 texel = textureLod(sampler2D(matc_lut, matc_lut_sampler), matc_lut_texcoord(uv.x, uv.y), 0.0);
#if MATC_COST_TABLE
  vec3 f = matc_fresnel_preintegrated(c, texel);
#elif MATC_COST_OURS
  vec3 f = matc_fresnel_preintegrated_{{name}}(texel);
#else
  // The table baked from ComparisonLobes: x = albedo, y = Schlick's lobe.
  vec3 f = F0 * texel.x + (vec3(1.0) - F0) * texel.y;
#endif
  colour = vec4(f, 1.0);
#endif
}
