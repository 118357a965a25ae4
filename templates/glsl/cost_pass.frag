#version 450
// matc {{version}}: the full-screen pass of the cost benchmark (bench/fullscreen_cost.cpp). Both
// variants read the same RGBA32F table once through the same texture coordinates and write the
// same target; only the Fresnel differs: {{variant}}.
{{defines}}
{{library}}
{{material}}
layout(set = 0, binding = 0) uniform texture2D matc_lut;
layout(set = 0, binding = 1) uniform sampler matc_lut_sampler;
layout(location = 0) out vec4 colour;

const vec3 F0 = vec3({{f0}});

void main() {
  // Every pixel a different (NdotV, roughness), like the pixels of a shaded object.
  vec2 uv = gl_FragCoord.xy / vec2({{width}}.0, {{height}}.0);
#if MATC_COST_DIRECT
  float mu = uv.x;
#if MATC_COST_OURS
  vec3 f = matc_fresnel_{{name}}(mu);
#else
  vec3 f = F0 + (vec3(1.0) - F0) * pow(1.0 - mu, 5.0);
#endif
  colour = vec4(f * uv.y, 1.0);
#else
  vec4 texel = textureLod(sampler2D(matc_lut, matc_lut_sampler), matc_lut_texcoord(uv.x, uv.y), 0.0);
#if MATC_COST_OURS
  vec3 f = matc_fresnel_preintegrated_{{name}}(texel);
#else
  // The table baked from ComparisonLobes: x = albedo, y = Schlick's lobe.
  vec3 f = F0 * texel.x + (vec3(1.0) - F0) * texel.y;
#endif
  colour = vec4(f, 1.0);
#endif
}
