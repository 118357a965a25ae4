
// ---- Area lights: linearly transformed cosines (Heitz, Dupuy, Hill, Neubelt 2016) ----
// L = I_ltc(light) * matc_fresnel_preintegrated(c, bbar): the LTC table (matc_ltc.*) gives the
// lobe's shape, the preintegrated table its magnitude and Fresnel (docs/ltc.md). The *_following
// functions are the quality level: the lobe's shape and the Fresnel follow the light. Lights are
// two-sided with radiance 1: scale by the light's radiance.

// Width and height of the LTC table this build wrote (matc_ltc.*).
#define MATC_LTC_SIZE {{ltc_size}}

// Where to sample the LTC table: 1 - sqrt(1 - NdotV), nearly linear in the view angle so that the
// lobe's direction interpolates between texels (docs/ltc.md), and roughness.
vec2 matc_ltc_texcoord(float NdotV, float roughness) {
  vec2 axes = vec2(1.0 - sqrt(1.0 - clamp(NdotV, 0.0, 1.0)), clamp(roughness, 0.0, 1.0));
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
// sum: z is the form factor's, x and y say where the lit part lies (the quality level).
struct MatcLtcPolygon {
  vec3 sum;
  vec3 exit_point;
  vec3 entry_point;
  bool exits;
  bool enters;
};

MatcLtcPolygon matc_ltc_polygon_start() {
  return MatcLtcPolygon(vec3(0.0), vec3(0.0), vec3(0.0), false, false);
}

// theta * normalize(a x b) for unit vectors a, b (atan2 stays accurate for short arcs); the
// one-shape path reads only z, and compilers drop x and y there.
vec3 matc_ltc_edge(vec3 a, vec3 b) {
  vec3 n = cross(a, b);
  float s = length(n);
  return s > 0.0 ? n * (atan(s, dot(a, b)) / s) : vec3(0.0);
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

// The closed polygon's sum: 2 pi times the vector form factor, either sign.
vec3 matc_ltc_polygon_sum(MatcLtcPolygon polygon) {
  vec3 sum = polygon.sum;
  if (polygon.exits && polygon.enters) sum += matc_ltc_edge(polygon.exit_point, polygon.entry_point);
  return sum;
}

float matc_ltc_polygon_result(MatcLtcPolygon polygon) {
  return min(abs(matc_ltc_polygon_sum(polygon).z) * 0.15915494309189535, 1.0);  // 1 / (2 pi)
}

// A convex planar quad q0..q3 (world space, either winding) seen from P, integrated.
MatcLtcPolygon matc_ltc_quad_polygon(mat3 transform, vec3 P, vec3 q0, vec3 q1, vec3 q2, vec3 q3) {
  vec3 a = transform * (q0 - P);
  vec3 b = transform * (q1 - P);
  vec3 c = transform * (q2 - P);
  vec3 d = transform * (q3 - P);
  MatcLtcPolygon polygon = matc_ltc_polygon_start();
  matc_ltc_add_edge(polygon, a, b);
  matc_ltc_add_edge(polygon, b, c);
  matc_ltc_add_edge(polygon, c, d);
  matc_ltc_add_edge(polygon, d, a);
  return polygon;
}

// The LTC's integral over a convex planar quad q0..q3 (world space, either winding) seen from P.
float matc_ltc_quad_integral(mat3 transform, vec3 P, vec3 q0, vec3 q1, vec3 q2, vec3 q3) {
  return matc_ltc_polygon_result(matc_ltc_quad_polygon(transform, P, q0, q1, q2, q3));
}

// A disk light (centre, normal, radius) as a regular {{disk_sides}}-gon of the same area.
MatcLtcPolygon matc_ltc_disk_polygon(mat3 transform, vec3 P, vec3 centre, vec3 normal,
                                     float radius) {
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
  return polygon;
}

float matc_ltc_disk_integral(mat3 transform, vec3 P, vec3 centre, vec3 normal, float radius) {
  return matc_ltc_polygon_result(matc_ltc_disk_polygon(transform, P, centre, normal, radius));
}

// A sphere light (centre, radius; P outside it): the disk at its centre facing P that fills the
// same cone of directions, radius * d / sqrt(d^2 - radius^2) for the distance d.
MatcLtcPolygon matc_ltc_sphere_polygon(mat3 transform, vec3 P, vec3 centre, float radius) {
  vec3 towards = P - centre;
  float d2 = dot(towards, towards);
  float disk_radius = radius * sqrt(d2 / max(d2 - radius * radius, 1e-30));
  return matc_ltc_disk_polygon(transform, P, centre, towards, disk_radius);
}

float matc_ltc_sphere_integral(mat3 transform, vec3 P, vec3 centre, float radius) {
  return matc_ltc_polygon_result(matc_ltc_sphere_polygon(transform, P, centre, radius));
}

// The GGX lobe without Fresnel, f cos (height-correlated Smith), at a unit L in the shading
// frame (V in the xz-plane at NdotV): what the LTC approximates.
float matc_ltc_ggx_lobe(float NdotV, float roughness, vec3 L) {
  float nv = clamp(NdotV, 1e-3, 1.0);
  float alpha = max(roughness * roughness, 1e-4);
  float a2 = alpha * alpha;
  vec3 H = normalize(vec3(sqrt(1.0 - nv * nv), 0.0, nv) + L);
  // 1 - H.z * H.z as H.x * H.x + H.y * H.y: float32 loses the difference near the peak.
  float d = H.x * H.x + H.y * H.y + H.z * H.z * a2;
  float D = a2 / (3.14159265358979 * d * d);
  float nl = L.z;
  float smith =
      0.5 / (nl * sqrt(nv * nv * (1.0 - a2) + a2) + nv * sqrt(nl * nl * (1.0 - a2) + a2));
  return nl > 0.0 ? D * smith * nl : 0.0;
}

// The quality level's geometry for a polygon (docs/ltc.md): (I', V.H, I). Where the light lies on
// the lobe is the direction L of the vector form factor f taken back through M (the adjugate of
// M^-1; ad - bc > 0 in every texel). I' = I mix(r, 1, s): r, the lobe's f cos over albedo times
// the LTC's density at L (u.z |adj u|^3 / (pi det^2) for u = f / |f|), clamped to [0, 4]; s =
// q (2 - q) for q = sqrt(|f|), from the light's size. V.H = sqrt((1 + V.L) / 2).
vec3 matc_ltc_following_geometry(MatcLtcPolygon polygon, vec4 ltc, float NdotV, float roughness,
                                 float albedo) {
  vec3 f = matc_ltc_polygon_sum(polygon) * 0.15915494309189535;  // 1 / (2 pi)
  f = f.z < 0.0 ? -f : f;
  float length_f = length(f);
  vec3 u = f / max(length_f, 1e-30);
  float det = ltc.x * ltc.w - ltc.y * ltc.z;
  vec3 back = vec3(ltc.w * u.x - ltc.y * u.z, det * u.y, ltc.x * u.z - ltc.z * u.x);
  float back_length = length(back);
  vec3 L = back / max(back_length, 1e-30);
  float ndotv = clamp(NdotV, 0.0, 1.0);
  vec3 V = vec3(sqrt(1.0 - ndotv * ndotv), 0.0, ndotv);
  float vdoth = sqrt(clamp(0.5 + 0.5 * dot(V, L), 0.0, 1.0));
  float ratio = clamp(matc_ltc_ggx_lobe(NdotV, roughness, L) * 3.14159265358979 * det * det /
                          max(albedo * u.z * back_length * back_length * back_length, 1e-30),
                      0.0, 4.0);
  float integral = min(f.z, 1.0);
  float root = sqrt(min(length_f, 1.0));
  return vec3(integral * mix(ratio, 1.0, root * (2.0 - root)), vdoth, integral);
}

// The quality level's radiance: L = I' mix(E F_light, Fbar, I), E = bbar.x the lobe's albedo,
// F_light the Fresnel at V.H = geometry.y and Fbar the preintegrated Fresnel: a light over a small
// part of the lobe sees the Fresnel where it lies, one over all of it the lobe's average.
vec3 matc_ltc_following_radiance(vec3 geometry, vec4 bbar, vec3 f_light, vec3 fbar) {
  return geometry.x * mix(bbar.x * f_light, fbar, geometry.z);
}

{{following}}
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

{{following_lights}}