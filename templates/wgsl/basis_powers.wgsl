// The basis b_0..b_3 at mu = cos(theta), in closed form (matc's {{basis}} basis): with m = 1 - mu,
// b_1 = m^{{edge_power}}, b_2 = mu m^{{lobe_power}} and b_3 = mu m^{{product_power}} = b_2 b_1 (unscaled: the tables are floating point).
// {{multiplies}} multiplies.
fn matc_basis{{suffix}}(mu: f32) -> vec4f {
  let x = clamp(mu, 0.0, 1.0);
  let m = 1.0 - x;
{{powers}}
  return vec4f(1.0, b1, b2, b2 * b1);
}

// F for a direct light (mu = dot(V, H)) without the clamp at 0, for curves matc proved
// non-negative (docs/shaders.md). sum_i c_i b_i written as {{sum_comment}}: three multiply-adds a channel, the cheapest order on AMD's ISA
// (bench/gpu_cost.cpp).
fn matc_fresnel_sum{{suffix}}(c: MatcFresnelCoefficients, mu: f32) -> vec3f {
{{sum_basis}}
  let c0 = vec3f(c.red.x, c.green.x, c.blue.x);
  let c1 = vec3f(c.red.y, c.green.y, c.blue.y);
  let c2 = vec3f(c.red.z, c.green.z, c.blue.z);
  let c3 = vec3f(c.red.w, c.green.w, c.blue.w);
  return {{sum}};
}

// F clamped at 0, where a truncated curve dips below it: what every coefficient source may use.
fn matc_fresnel{{suffix}}(c: MatcFresnelCoefficients, mu: f32) -> vec3f {
  return max(matc_fresnel_sum{{suffix}}(c, mu), vec3f(0.0));
}
