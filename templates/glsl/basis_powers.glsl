// The basis b_0..b_3 at mu = cos(theta), in closed form (matc's {{basis}} basis): with m = 1 - mu,
// b_1 = m^{{edge_power}}, b_2 = mu m^{{lobe_power}} and b_3 = mu m^{{product_power}} = b_2 b_1 (unscaled: the tables are floating point).
// {{multiplies}} multiplies.
vec4 matc_basis{{suffix}}(float mu) {
  float x = clamp(mu, 0.0, 1.0);
  float m = 1.0 - x;
{{powers}}
  return vec4(1.0, b1, b2, b2 * b1);
}

// F for a direct light (mu = dot(V, H)) without the clamp at 0, for curves matc proved
// non-negative (docs/shaders.md). sum_i c_i b_i written as {{sum_comment}}: three multiply-adds a channel, the cheapest order on AMD's ISA
// (bench/gpu_cost.cpp).
vec3 matc_fresnel_sum{{suffix}}(MatcFresnelCoefficients c, float mu) {
{{sum_basis}}
  vec3 c0 = vec3(c.red.x, c.green.x, c.blue.x);
  vec3 c1 = vec3(c.red.y, c.green.y, c.blue.y);
  vec3 c2 = vec3(c.red.z, c.green.z, c.blue.z);
  vec3 c3 = vec3(c.red.w, c.green.w, c.blue.w);
  return {{sum}};
}

// F clamped at 0, where a truncated curve dips below it: what every coefficient source may use.
vec3 matc_fresnel{{suffix}}(MatcFresnelCoefficients c, float mu) {
  return max(matc_fresnel_sum{{suffix}}(c, mu), vec3(0.0));
}
