// One polynomial coefficient of the segment: chosen with selects rather than by indexing a
// constant array, which compilers turn into memory traffic.
vec3 matc_basis_coefficient(int segment, vec3 s0, vec3 s1, vec3 s2, vec3 s3) {
  bvec3 odd = bvec3((segment & 1) != 0);
  return mix(mix(s0, s1, odd), mix(s2, s3, odd), bvec3(segment >= 2));
}

// The basis b_0..b_3 at mu = cos(theta): b_1..b_3 are {{segments}} polynomials of degree {{degree}}
// in u = sqrt(mu), each in t in [-1, 1] across its quarter of u, evaluated by Horner's rule.
vec4 matc_basis(float mu) {
  float scaled = sqrt(clamp(mu, 0.0, 1.0)) * {{segments}}.0;
  int segment = min(int(scaled), {{last_segment}});
  float t = 2.0 * (scaled - float(segment)) - 1.0;
{{horner_steps}}
  return vec4(1.0, b);
}

// F for a direct light: mu = dot(V, H).
vec3 matc_fresnel(MatcFresnelCoefficients c, float mu) {
  return matc_combine(c, matc_basis(mu));
}

// The same without the clamp at 0, for curves matc proved non-negative (docs/shaders.md).
vec3 matc_fresnel_sum(MatcFresnelCoefficients c, float mu) {
  return matc_combine_sum(c, matc_basis(mu));
}
