// The environment and sampling shared by the comparison renders (comparison_render.frag,
// textured_render.frag): a procedural sky, Hammersley points, GGX visible-normal sampling.
const float PI = 3.14159265358979;

// Radiance arriving from direction d (y up): sky, ground and two large soft lights, one behind
// the sphere so that its rim, where Fresnel differs most, reflects something bright.
vec3 environment(vec3 d) {
  vec3 horizon = vec3(0.85, 0.82, 0.78);
  vec3 sky = mix(horizon, vec3(0.18, 0.32, 0.65), sqrt(max(d.y, 0.0)));
  vec3 ground = mix(horizon * 0.5, vec3(0.16, 0.14, 0.12), sqrt(max(-d.y, 0.0)));
  vec3 c = d.y >= 0.0 ? sky : ground;
  c += vec3(5.0) * smoothstep(0.80, 0.95, dot(d, normalize(vec3(0.25, 0.45, -1.0))));
  c += vec3(3.0, 2.9, 2.7) * smoothstep(0.92, 0.98, dot(d, normalize(vec3(-1.0, 0.35, 0.25))));
  return c;
}

uint hash(uint x) {  // PCG output permutation
  x = x * 747796405u + 2891336453u;
  x = ((x >> ((x >> 28u) + 4u)) ^ x) * 277803737u;
  return (x >> 22u) ^ x;
}

// Hammersley point i of n, shifted per pixel (Cranley-Patterson rotation).
vec2 sample_point(uint i, uint n, vec2 shift) {
  vec2 u = vec2((float(i) + 0.5) / float(n), float(bitfieldReverse(i)) * 2.3283064365386963e-10);
  return fract(u + shift);
}

// An orthonormal frame around unit n (Duff et al. 2017).
void frame(vec3 n, out vec3 t, out vec3 b) {
  float s = n.z >= 0.0 ? 1.0 : -1.0;
  float a = -1.0 / (s + n.z);
  float c = n.x * n.y * a;
  t = vec3(1.0 + s * n.x * n.x * a, s * c, -s * n.x);
  b = vec3(c, s + n.y * n.y * a, -n.y);
}

// Smith's Lambda for GGX.
float smith_lambda(float cos_theta, float alpha) {
  float c2 = cos_theta * cos_theta;
  return 0.5 * (sqrt(1.0 + alpha * alpha * (1.0 - c2) / c2) - 1.0);
}

// Heitz 2018, "Sampling the GGX Distribution of Visible Normals"; v in the frame of the normal.
vec3 sample_visible_normal(vec3 v, float alpha, vec2 u) {
  vec3 vh = normalize(vec3(alpha * v.x, alpha * v.y, v.z));
  float length2 = vh.x * vh.x + vh.y * vh.y;
  vec3 t1 = length2 > 0.0 ? vec3(-vh.y, vh.x, 0.0) * inversesqrt(length2) : vec3(1.0, 0.0, 0.0);
  vec3 t2 = cross(vh, t1);
  float r = sqrt(u.x);
  float phi = 2.0 * PI * u.y;
  float p1 = r * cos(phi);
  float s = 0.5 * (1.0 + vh.z);
  float p2 = (1.0 - s) * sqrt(1.0 - p1 * p1) + s * r * sin(phi);
  vec3 nh = p1 * t1 + p2 * t2 + sqrt(max(0.0, 1.0 - p1 * p1 - p2 * p2)) * vh;
  return normalize(vec3(alpha * nh.x, alpha * nh.y, max(0.0, nh.z)));
}

// A GGX normal with density D(h) cos(theta_h), in the frame of the normal.
vec3 sample_normal(float alpha, vec2 u) {
  float cos2 = (1.0 - u.x) / (1.0 + (alpha * alpha - 1.0) * u.x);
  float sin_theta = sqrt(max(0.0, 1.0 - cos2));
  float phi = 2.0 * PI * u.y;
  return vec3(sin_theta * cos(phi), sin_theta * sin(phi), sqrt(cos2));
}
