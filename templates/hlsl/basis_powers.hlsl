// The basis b_0..b_3 at mu = cos(theta), in closed form (matc's {{basis}} basis): with m = 1 - mu,
// b_1 = m^{{edge_power}}, b_2 = mu m^{{lobe_power}} and b_3 = mu m^{{product_power}} = b_2 b_1 (unscaled: the tables are floating point).
// {{multiplies}} multiplies.
float4 matc_basis{{suffix}}(float mu) {
  float x = saturate(mu);
  float m = 1.0 - x;
{{powers}}
  return float4(1.0, b1, b2, b2 * b1);
}

// F for a direct light (mu = dot(V, H)) without the clamp at 0, for curves matc proved
// non-negative (docs/shaders.md). sum_i c_i b_i written as {{sum_comment}}: three multiply-adds a channel, the cheapest order on AMD's ISA
// (bench/gpu_cost.cpp).
float3 matc_fresnel_sum{{suffix}}(MatcFresnelCoefficients c, float mu) {
{{sum_basis}}
  float3 c0 = float3(c.red.x, c.green.x, c.blue.x);
  float3 c1 = float3(c.red.y, c.green.y, c.blue.y);
  float3 c2 = float3(c.red.z, c.green.z, c.blue.z);
  float3 c3 = float3(c.red.w, c.green.w, c.blue.w);
  return {{sum}};
}

// F clamped at 0, where a truncated curve dips below it: what every coefficient source may use.
float3 matc_fresnel{{suffix}}(MatcFresnelCoefficients c, float mu) {
  return max(matc_fresnel_sum{{suffix}}(c, mu), 0.0);
}
