
// ---- Area lights: linearly transformed cosines (Heitz, Dupuy, Hill, Neubelt 2016) ----
// L = I_ltc(light) * matc_fresnel_preintegrated(c, bbar): the LTC table (matc_ltc.*) gives the
// lobe's shape, the preintegrated table its magnitude and Fresnel (docs/ltc.md). The *_following
// functions are the quality level: the lobe's shape and the Fresnel follow the light. Lights are
// two-sided with radiance 1: scale by the light's radiance.

// Width and height of the LTC table this build wrote (matc_ltc.*).
#define MATC_LTC_SIZE {{ltc_size}}

// Where to sample the LTC table: 1 - sqrt(1 - NdotV), nearly linear in the view angle so that the
// lobe's direction interpolates between texels (docs/ltc.md), and roughness.
float2 matc_ltc_texcoord(float NdotV, float roughness) {
  float2 axes = float2(1.0 - sqrt(1.0 - saturate(NdotV)), saturate(roughness));
  // texcoord = (axes * (size - 1) + 0.5) / size, written as one multiply-add.
  return axes * (float(MATC_LTC_SIZE - 1) / float(MATC_LTC_SIZE)) + 0.5 / float(MATC_LTC_SIZE);
}

// World space to the LTC's cosine space for a shading point: the shading frame (T1 towards the
// view, T2, N), then M^-1 = ((a, 0, b), (0, 1, 0), (c, 0, d)) from the LTC texel (a, b, c, d).
float3x3 matc_ltc_transform(float3 N, float3 V, float4 ltc) {
  float3 tangent = V - N * dot(N, V);
  float tangent_length = length(tangent);
  // V along N: the lobe is symmetric about N, any tangent will do.
  float3 fallback = abs(N.z) < 0.999 ? float3(0.0, 0.0, 1.0) : float3(1.0, 0.0, 0.0);
  float3 T1 = tangent_length > 1e-6 ? tangent / tangent_length : normalize(cross(N, fallback));
  float3 T2 = cross(N, T1);
  float3x3 to_frame = float3x3(T1, T2, N);  // rows
  float3x3 inverse_m = float3x3(float3(ltc.x, 0.0, ltc.y), float3(0.0, 1.0, 0.0),
                                float3(ltc.z, 0.0, ltc.w));
  return mul(inverse_m, to_frame);
}

// A polygon integrated edge by edge, clipped at the cosine's horizon as it goes: a convex polygon
// leaves the upper hemisphere once and comes back once, and the horizon arc closes it.
// sum: z is the form factor's, x and y say where the lit part lies (the quality level).
struct MatcLtcPolygon {
  float3 sum;
  float3 exit_point;
  float3 entry_point;
  bool exits;
  bool enters;
};

MatcLtcPolygon matc_ltc_polygon_start() {
  MatcLtcPolygon polygon;
  polygon.sum = float3(0.0, 0.0, 0.0);
  polygon.exit_point = float3(0.0, 0.0, 0.0);
  polygon.entry_point = float3(0.0, 0.0, 0.0);
  polygon.exits = false;
  polygon.enters = false;
  return polygon;
}

// theta * normalize(a x b) for unit vectors a, b (atan2 stays accurate for short arcs); the
// one-shape path reads only z, and compilers drop x and y there.
float3 matc_ltc_edge(float3 a, float3 b) {
  float3 n = cross(a, b);
  float s = length(n);
  return s > 0.0 ? n * (atan2(s, dot(a, b)) / s) : float3(0.0, 0.0, 0.0);
}

void matc_ltc_add_edge(inout MatcLtcPolygon polygon, float3 a, float3 b) {
  bool a_above = a.z > 0.0;
  bool b_above = b.z > 0.0;
  if (a_above && b_above) {
    polygon.sum += matc_ltc_edge(normalize(a), normalize(b));
  } else if (a_above) {
    float3 p = lerp(a, b, a.z / (a.z - b.z));
    polygon.exit_point = normalize(float3(p.xy, 0.0));
    polygon.exits = true;
    polygon.sum += matc_ltc_edge(normalize(a), polygon.exit_point);
  } else if (b_above) {
    float3 p = lerp(b, a, b.z / (b.z - a.z));
    polygon.entry_point = normalize(float3(p.xy, 0.0));
    polygon.enters = true;
    polygon.sum += matc_ltc_edge(polygon.entry_point, normalize(b));
  }
}

// The closed polygon's sum: 2 pi times the vector form factor, either sign.
float3 matc_ltc_polygon_sum(MatcLtcPolygon polygon) {
  float3 sum = polygon.sum;
  if (polygon.exits && polygon.enters) sum += matc_ltc_edge(polygon.exit_point, polygon.entry_point);
  return sum;
}

float matc_ltc_polygon_result(MatcLtcPolygon polygon) {
  return min(abs(matc_ltc_polygon_sum(polygon).z) * 0.15915494309189535, 1.0);  // 1 / (2 pi)
}

// A convex planar quad q0..q3 (world space, either winding) seen from P, integrated.
MatcLtcPolygon matc_ltc_quad_polygon(float3x3 transform, float3 P, float3 q0, float3 q1, float3 q2,
                                     float3 q3) {
  float3 a = mul(transform, q0 - P);
  float3 b = mul(transform, q1 - P);
  float3 c = mul(transform, q2 - P);
  float3 d = mul(transform, q3 - P);
  MatcLtcPolygon polygon = matc_ltc_polygon_start();
  matc_ltc_add_edge(polygon, a, b);
  matc_ltc_add_edge(polygon, b, c);
  matc_ltc_add_edge(polygon, c, d);
  matc_ltc_add_edge(polygon, d, a);
  return polygon;
}

// The LTC's integral over a convex planar quad q0..q3 (world space, either winding) seen from P.
float matc_ltc_quad_integral(float3x3 transform, float3 P, float3 q0, float3 q1, float3 q2, float3 q3) {
  return matc_ltc_polygon_result(matc_ltc_quad_polygon(transform, P, q0, q1, q2, q3));
}

// A disk light (centre, normal, radius) as a regular {{disk_sides}}-gon of the same area.
MatcLtcPolygon matc_ltc_disk_polygon(float3x3 transform, float3 P, float3 centre, float3 normal,
                                     float radius) {
  // An orthonormal basis around the normal (Duff et al. 2017).
  float3 n = normalize(normal);
  float sign_z = n.z >= 0.0 ? 1.0 : -1.0;
  float a = -1.0 / (sign_z + n.z);
  float b = n.x * n.y * a;
  float3 tangent = float3(1.0 + sign_z * n.x * n.x * a, sign_z * b, -sign_z * n.x);
  float3 bitangent = float3(b, sign_z + n.y * n.y * a, -n.y);
  float circumradius = radius * {{disk_circumradius_scale}};
  float3 u = mul(transform, tangent * circumradius);
  float3 v = mul(transform, bitangent * circumradius);
  float3 o = mul(transform, centre - P);
  MatcLtcPolygon polygon = matc_ltc_polygon_start();
  float3 first = o + u;
  float3 previous = first;
  for (int i = 1; i < {{disk_sides}}; ++i) {
    float angle = float(i) * {{disk_angle_step}};
    float3 current = o + cos(angle) * u + sin(angle) * v;
    matc_ltc_add_edge(polygon, previous, current);
    previous = current;
  }
  matc_ltc_add_edge(polygon, previous, first);
  return polygon;
}

float matc_ltc_disk_integral(float3x3 transform, float3 P, float3 centre, float3 normal, float radius) {
  return matc_ltc_polygon_result(matc_ltc_disk_polygon(transform, P, centre, normal, radius));
}

// A sphere light (centre, radius; P outside it): the disk at its centre facing P that fills the
// same cone of directions, radius * d / sqrt(d^2 - radius^2) for the distance d.
MatcLtcPolygon matc_ltc_sphere_polygon(float3x3 transform, float3 P, float3 centre, float radius) {
  float3 towards = P - centre;
  float d2 = dot(towards, towards);
  float disk_radius = radius * sqrt(d2 / max(d2 - radius * radius, 1e-30));
  return matc_ltc_disk_polygon(transform, P, centre, towards, disk_radius);
}

float matc_ltc_sphere_integral(float3x3 transform, float3 P, float3 centre, float radius) {
  return matc_ltc_polygon_result(matc_ltc_sphere_polygon(transform, P, centre, radius));
}

// The GGX lobe without Fresnel, f cos (height-correlated Smith), at a unit L in the shading
// frame (V in the xz-plane at NdotV): what the LTC approximates.
float matc_ltc_ggx_lobe(float NdotV, float roughness, float3 L) {
  float nv = clamp(NdotV, 1e-3, 1.0);
  float alpha = max(roughness * roughness, 1e-4);
  float a2 = alpha * alpha;
  float3 H = normalize(float3(sqrt(1.0 - nv * nv), 0.0, nv) + L);
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
// M^-1; ad - bc > 0 in every texel). I' = I lerp(r, 1, s): r, the lobe's f cos over albedo times
// the LTC's density at L (u.z |adj u|^3 / (pi det^2) for u = f / |f|), clamped to [0, 4]; s =
// q (2 - q) for q = sqrt(|f|), from the light's size. V.H = sqrt((1 + V.L) / 2).
float3 matc_ltc_following_geometry(MatcLtcPolygon polygon, float4 ltc, float NdotV,
                                   float roughness, float albedo) {
  float3 f = matc_ltc_polygon_sum(polygon) * 0.15915494309189535;  // 1 / (2 pi)
  f = f.z < 0.0 ? -f : f;
  float length_f = length(f);
  float3 u = f / max(length_f, 1e-30);
  float det = ltc.x * ltc.w - ltc.y * ltc.z;
  float3 back = float3(ltc.w * u.x - ltc.y * u.z, det * u.y, ltc.x * u.z - ltc.z * u.x);
  float back_length = length(back);
  float3 L = back / max(back_length, 1e-30);
  float ndotv = saturate(NdotV);
  float3 V = float3(sqrt(1.0 - ndotv * ndotv), 0.0, ndotv);
  float vdoth = sqrt(saturate(0.5 + 0.5 * dot(V, L)));
  float ratio = clamp(matc_ltc_ggx_lobe(NdotV, roughness, L) * 3.14159265358979 * det * det /
                          max(albedo * u.z * back_length * back_length * back_length, 1e-30),
                      0.0, 4.0);
  float integral = min(f.z, 1.0);
  float root = sqrt(min(length_f, 1.0));
  return float3(integral * lerp(ratio, 1.0, root * (2.0 - root)), vdoth, integral);
}

// The quality level's radiance: L = I' lerp(E F_light, Fbar, I), E = bbar.x the lobe's albedo,
// F_light the Fresnel at V.H = geometry.y and Fbar the preintegrated Fresnel: a light over a small
// part of the lobe sees the Fresnel where it lies, one over all of it the lobe's average.
float3 matc_ltc_following_radiance(float3 geometry, float4 bbar, float3 f_light, float3 fbar) {
  return geometry.x * lerp(bbar.x * f_light, fbar, geometry.z);
}

{{following}}
// Radiance from a quad light of radiance 1: bbar from matc_lut and ltc from matc_ltc, both at
// their texcoords for (NdotV, roughness).
float3 matc_ltc_quad_light(MatcFresnelCoefficients c, float4 bbar, float4 ltc, float3 N, float3 V, float3 P,
                         float3 q0, float3 q1, float3 q2, float3 q3) {
  return matc_ltc_quad_integral(matc_ltc_transform(N, V, ltc), P, q0, q1, q2, q3) *
         matc_fresnel_preintegrated(c, bbar);
}

// ... and from a disk light of radiance 1.
float3 matc_ltc_disk_light(MatcFresnelCoefficients c, float4 bbar, float4 ltc, float3 N, float3 V, float3 P,
                         float3 centre, float3 normal, float radius) {
  return matc_ltc_disk_integral(matc_ltc_transform(N, V, ltc), P, centre, normal, radius) *
         matc_fresnel_preintegrated(c, bbar);
}

// ... and from a sphere light of radiance 1.
float3 matc_ltc_sphere_light(MatcFresnelCoefficients c, float4 bbar, float4 ltc, float3 N, float3 V,
                           float3 P, float3 centre, float radius) {
  return matc_ltc_sphere_integral(matc_ltc_transform(N, V, ltc), P, centre, radius) *
         matc_fresnel_preintegrated(c, bbar);
}

{{following_lights}}