// One polynomial coefficient of the segment: chosen with selects rather than by indexing a
// constant array, which compilers turn into memory traffic.
fn matc_basis_coefficient(segment: i32, s0: vec3f, s1: vec3f, s2: vec3f, s3: vec3f) -> vec3f {
  let odd = (segment & 1) != 0;
  return select(select(s0, s1, odd), select(s2, s3, odd), segment >= 2);
}

// The basis b_0..b_3 at mu = cos(theta): b_1..b_3 are {{segments}} polynomials of degree {{degree}}
// in u = sqrt(mu), each in t in [-1, 1] across its quarter of u, evaluated by Horner's rule.
fn matc_basis(mu: f32) -> vec4f {
  let scaled = sqrt(clamp(mu, 0.0, 1.0)) * {{segments}}.0;
  let segment = min(i32(scaled), {{last_segment}});
  let t = 2.0 * (scaled - f32(segment)) - 1.0;
{{horner_steps}}
  return vec4f(1.0, b);
}

// F for a direct light: mu = dot(V, H).
fn matc_fresnel(c: MatcFresnelCoefficients, mu: f32) -> vec3f {
  return matc_combine(c, matc_basis(mu));
}

// The same without the clamp at 0, for curves matc proved non-negative (docs/shaders.md).
fn matc_fresnel_sum(c: MatcFresnelCoefficients, mu: f32) -> vec3f {
  return matc_combine_sum(c, matc_basis(mu));
}
