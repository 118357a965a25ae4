
// ---- Area lights: linearly transformed cosines (Heitz, Dupuy, Hill, Neubelt 2016) ----
// L = I_ltc(light) * matc_fresnel_preintegrated(c, bbar): the LTC table (matc_ltc.*) gives the
// lobe's shape, the preintegrated table its magnitude and Fresnel (docs/ltc.md). Lights are
// two-sided with radiance 1: scale by the light's radiance.

// Width and height of the LTC table this build wrote (matc_ltc.*).
#define MATC_LTC_SIZE {{ltc_size}}

// Where to sample the LTC table: the preintegrated table's axes, at the LTC table's size.
vec2 matc_ltc_texcoord(float NdotV, float roughness) {
  vec2 axes = vec2(sqrt(clamp(NdotV, 0.0, 1.0)), clamp(roughness, 0.0, 1.0));
  // texcoord = (axes * (size - 1) + 0.5) / size, written as one multiply-add.
  return axes * (float(MATC_LTC_SIZE - 1) / float(MATC_LTC_SIZE)) + 0.5 / float(MATC_LTC_SIZE);
}

// World space to the LTC's cosine space for a shading point: the shading frame (T1 towards the
// view, T2, N), then M^-1 = ((a, 0, b), (0, 1, 0), (c, 0, d)) from the LTC texel (a, b, c, d).
mat3 matc_ltc_transform(vec3 N, vec3 V, vec4 ltc) {
  vec3 tangent = V - N * dot(N, V);
  float tangent_length = length(tangent);
  // V along N: the lobe is symmetric about N, any tangent will do.
  vec3 fallback = abs(N.z) < 0.999 ? vec3(0.0, 0.0, 1.0) : vec3(1.0, 0.0, 0.0);
  vec3 T1 = tangent_length > 1e-6 ? tangent / tangent_length : normalize(cross(N, fallback));
  vec3 T2 = cross(N, T1);
  mat3 to_frame = transpose(mat3(T1, T2, N));
  mat3 inverse_m = transpose(mat3(vec3(ltc.x, 0.0, ltc.y), vec3(0.0, 1.0, 0.0),
                                  vec3(ltc.z, 0.0, ltc.w)));
  return inverse_m * to_frame;
}

// A polygon integrated edge by edge, clipped at the cosine's horizon as it goes: a convex polygon
// leaves the upper hemisphere once and comes back once, and the horizon arc closes it.
struct MatcLtcPolygon {
  float sum;
  vec3 exit_point;
  vec3 entry_point;
  bool exits;
  bool enters;
};

MatcLtcPolygon matc_ltc_polygon_start() {
  return MatcLtcPolygon(0.0, vec3(0.0), vec3(0.0), false, false);
}

// theta * normalize(a x b).z for unit vectors a, b (atan2 stays accurate for short arcs).
float matc_ltc_edge(vec3 a, vec3 b) {
  vec3 n = cross(a, b);
  float s = length(n);
  return s > 0.0 ? n.z * (atan(s, dot(a, b)) / s) : 0.0;
}

void matc_ltc_add_edge(inout MatcLtcPolygon polygon, vec3 a, vec3 b) {
  bool a_above = a.z > 0.0;
  bool b_above = b.z > 0.0;
  if (a_above && b_above) {
    polygon.sum += matc_ltc_edge(normalize(a), normalize(b));
  } else if (a_above) {
    vec3 p = mix(a, b, a.z / (a.z - b.z));
    polygon.exit_point = normalize(vec3(p.xy, 0.0));
    polygon.exits = true;
    polygon.sum += matc_ltc_edge(normalize(a), polygon.exit_point);
  } else if (b_above) {
    vec3 p = mix(b, a, b.z / (b.z - a.z));
    polygon.entry_point = normalize(vec3(p.xy, 0.0));
    polygon.enters = true;
    polygon.sum += matc_ltc_edge(polygon.entry_point, normalize(b));
  }
}

float matc_ltc_polygon_result(MatcLtcPolygon polygon) {
  float sum = polygon.sum;
  if (polygon.exits && polygon.enters) sum += matc_ltc_edge(polygon.exit_point, polygon.entry_point);
  return min(abs(sum) * 0.15915494309189535, 1.0);  // 1 / (2 pi)
}

// The LTC's integral over a convex planar quad q0..q3 (world space, either winding) seen from P.
float matc_ltc_quad_integral(mat3 transform, vec3 P, vec3 q0, vec3 q1, vec3 q2, vec3 q3) {
  vec3 a = transform * (q0 - P);
  vec3 b = transform * (q1 - P);
  vec3 c = transform * (q2 - P);
  vec3 d = transform * (q3 - P);
  MatcLtcPolygon polygon = matc_ltc_polygon_start();
  matc_ltc_add_edge(polygon, a, b);
  matc_ltc_add_edge(polygon, b, c);
  matc_ltc_add_edge(polygon, c, d);
  matc_ltc_add_edge(polygon, d, a);
  return matc_ltc_polygon_result(polygon);
}

// A disk light (centre, normal, radius) as a regular {{disk_sides}}-gon of the same area.
float matc_ltc_disk_integral(mat3 transform, vec3 P, vec3 centre, vec3 normal, float radius) {
  // An orthonormal basis around the normal (Duff et al. 2017).
  vec3 n = normalize(normal);
  float sign_z = n.z >= 0.0 ? 1.0 : -1.0;
  float a = -1.0 / (sign_z + n.z);
  float b = n.x * n.y * a;
  vec3 tangent = vec3(1.0 + sign_z * n.x * n.x * a, sign_z * b, -sign_z * n.x);
  vec3 bitangent = vec3(b, sign_z + n.y * n.y * a, -n.y);
  float circumradius = radius * {{disk_circumradius_scale}};
  vec3 u = transform * (tangent * circumradius);
  vec3 v = transform * (bitangent * circumradius);
  vec3 o = transform * (centre - P);
  MatcLtcPolygon polygon = matc_ltc_polygon_start();
  vec3 first = o + u;
  vec3 previous = first;
  for (int i = 1; i < {{disk_sides}}; ++i) {
    float angle = float(i) * {{disk_angle_step}};
    vec3 current = o + cos(angle) * u + sin(angle) * v;
    matc_ltc_add_edge(polygon, previous, current);
    previous = current;
  }
  matc_ltc_add_edge(polygon, previous, first);
  return matc_ltc_polygon_result(polygon);
}

// A sphere light (centre, radius; P outside it): the disk at its centre facing P that fills the
// same cone of directions, radius * d / sqrt(d^2 - radius^2) for the distance d.
float matc_ltc_sphere_integral(mat3 transform, vec3 P, vec3 centre, float radius) {
  vec3 towards = P - centre;
  float d2 = dot(towards, towards);
  float disk_radius = radius * sqrt(d2 / max(d2 - radius * radius, 1e-30));
  return matc_ltc_disk_integral(transform, P, centre, towards, disk_radius);
}

// Radiance from a quad light of radiance 1: bbar from matc_lut and ltc from matc_ltc, both at
// their texcoords for (NdotV, roughness).
vec3 matc_ltc_quad_light(MatcFresnelCoefficients c, vec4 bbar, vec4 ltc, vec3 N, vec3 V, vec3 P,
                         vec3 q0, vec3 q1, vec3 q2, vec3 q3) {
  return matc_ltc_quad_integral(matc_ltc_transform(N, V, ltc), P, q0, q1, q2, q3) *
         matc_fresnel_preintegrated(c, bbar);
}

// ... and from a disk light of radiance 1.
vec3 matc_ltc_disk_light(MatcFresnelCoefficients c, vec4 bbar, vec4 ltc, vec3 N, vec3 V, vec3 P,
                         vec3 centre, vec3 normal, float radius) {
  return matc_ltc_disk_integral(matc_ltc_transform(N, V, ltc), P, centre, normal, radius) *
         matc_fresnel_preintegrated(c, bbar);
}

// ... and from a sphere light of radiance 1.
vec3 matc_ltc_sphere_light(MatcFresnelCoefficients c, vec4 bbar, vec4 ltc, vec3 N, vec3 V,
                           vec3 P, vec3 centre, float radius) {
  return matc_ltc_sphere_integral(matc_ltc_transform(N, V, ltc), P, centre, radius) *
         matc_fresnel_preintegrated(c, bbar);
}
