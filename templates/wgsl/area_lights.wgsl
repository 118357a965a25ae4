
// ---- Area lights: linearly transformed cosines (Heitz, Dupuy, Hill, Neubelt 2016) ----
// L = I_ltc(light) * matc_fresnel_preintegrated(c, bbar): the LTC table (matc_ltc.*) gives the
// lobe's shape, the preintegrated table its magnitude and Fresnel (docs/ltc.md). The *_following
// functions are the quality level: the lobe's shape and the Fresnel follow the light. Lights are
// two-sided with radiance 1: scale by the light's radiance. The LTC table is always f32: sampling
// it with a linear filter needs the device feature "float32-filterable".

// Width and height of the LTC table this build wrote (matc_ltc.*).
const MATC_LTC_SIZE: i32 = {{ltc_size}};

// Where to sample the LTC table: 1 - sqrt(1 - NdotV), nearly linear in the view angle so that the
// lobe's direction interpolates between texels (docs/ltc.md), and roughness.
fn matc_ltc_texcoord(NdotV: f32, roughness: f32) -> vec2f {
  let axes = vec2f(1.0 - sqrt(1.0 - clamp(NdotV, 0.0, 1.0)), clamp(roughness, 0.0, 1.0));
  // texcoord = (axes * (size - 1) + 0.5) / size, written as one multiply-add.
  return axes * (f32(MATC_LTC_SIZE - 1) / f32(MATC_LTC_SIZE)) + 0.5 / f32(MATC_LTC_SIZE);
}

// World space to the LTC's cosine space for a shading point: the shading frame (T1 towards the
// view, T2, N), then M^-1 = ((a, 0, b), (0, 1, 0), (c, 0, d)) from the LTC texel (a, b, c, d).
fn matc_ltc_transform(N: vec3f, V: vec3f, ltc: vec4f) -> mat3x3f {
  let tangent = V - N * dot(N, V);
  let tangent_length = length(tangent);
  // V along N: the lobe is symmetric about N, any tangent will do.
  let fallback = select(vec3f(1.0, 0.0, 0.0), vec3f(0.0, 0.0, 1.0), abs(N.z) < 0.999);
  var T1 = normalize(cross(N, fallback));
  if (tangent_length > 1e-6) {
    T1 = tangent / tangent_length;
  }
  let T2 = cross(N, T1);
  let to_frame = transpose(mat3x3f(T1, T2, N));
  let inverse_m = transpose(mat3x3f(vec3f(ltc.x, 0.0, ltc.y), vec3f(0.0, 1.0, 0.0),
                                    vec3f(ltc.z, 0.0, ltc.w)));
  return inverse_m * to_frame;
}

// A polygon integrated edge by edge, clipped at the cosine's horizon as it goes: a convex polygon
// leaves the upper hemisphere once and comes back once, and the horizon arc closes it.
// sum: z is the form factor's, x and y say where the lit part lies (the quality level).
struct MatcLtcPolygon {
  sum: vec3f,
  exit_point: vec3f,
  entry_point: vec3f,
  exits: bool,
  enters: bool,
}

fn matc_ltc_polygon_start() -> MatcLtcPolygon {
  return MatcLtcPolygon(vec3f(0.0), vec3f(0.0), vec3f(0.0), false, false);
}

// theta * normalize(a x b) for unit vectors a, b (atan2 stays accurate for short arcs); the
// one-shape path reads only z, and compilers drop x and y there.
fn matc_ltc_edge(a: vec3f, b: vec3f) -> vec3f {
  let n = cross(a, b);
  let s = length(n);
  if (s > 0.0) {
    return n * (atan2(s, dot(a, b)) / s);
  }
  return vec3f(0.0);
}

fn matc_ltc_add_edge(polygon: ptr<function, MatcLtcPolygon>, a: vec3f, b: vec3f) {
  let a_above = a.z > 0.0;
  let b_above = b.z > 0.0;
  if (a_above && b_above) {
    (*polygon).sum += matc_ltc_edge(normalize(a), normalize(b));
  } else if (a_above) {
    let p = mix(a, b, a.z / (a.z - b.z));
    (*polygon).exit_point = normalize(vec3f(p.xy, 0.0));
    (*polygon).exits = true;
    (*polygon).sum += matc_ltc_edge(normalize(a), (*polygon).exit_point);
  } else if (b_above) {
    let p = mix(b, a, b.z / (b.z - a.z));
    (*polygon).entry_point = normalize(vec3f(p.xy, 0.0));
    (*polygon).enters = true;
    (*polygon).sum += matc_ltc_edge((*polygon).entry_point, normalize(b));
  }
}

// The closed polygon's sum: 2 pi times the vector form factor, either sign.
fn matc_ltc_polygon_sum(polygon: MatcLtcPolygon) -> vec3f {
  var sum = polygon.sum;
  if (polygon.exits && polygon.enters) {
    sum += matc_ltc_edge(polygon.exit_point, polygon.entry_point);
  }
  return sum;
}

fn matc_ltc_polygon_result(polygon: MatcLtcPolygon) -> f32 {
  return min(abs(matc_ltc_polygon_sum(polygon).z) * 0.15915494309189535, 1.0);  // 1 / (2 pi)
}

// A convex planar quad q0..q3 (world space, either winding) seen from P, integrated.
fn matc_ltc_quad_polygon(transform: mat3x3f, P: vec3f, q0: vec3f, q1: vec3f, q2: vec3f,
                         q3: vec3f) -> MatcLtcPolygon {
  let a = transform * (q0 - P);
  let b = transform * (q1 - P);
  let c = transform * (q2 - P);
  let d = transform * (q3 - P);
  var polygon = matc_ltc_polygon_start();
  matc_ltc_add_edge(&polygon, a, b);
  matc_ltc_add_edge(&polygon, b, c);
  matc_ltc_add_edge(&polygon, c, d);
  matc_ltc_add_edge(&polygon, d, a);
  return polygon;
}

// The LTC's integral over a convex planar quad q0..q3 (world space, either winding) seen from P.
fn matc_ltc_quad_integral(transform: mat3x3f, P: vec3f, q0: vec3f, q1: vec3f, q2: vec3f,
                          q3: vec3f) -> f32 {
  return matc_ltc_polygon_result(matc_ltc_quad_polygon(transform, P, q0, q1, q2, q3));
}

// A disk light (centre, normal, radius) as a regular {{disk_sides}}-gon of the same area.
fn matc_ltc_disk_polygon(transform: mat3x3f, P: vec3f, centre: vec3f, normal: vec3f,
                         radius: f32) -> MatcLtcPolygon {
  // An orthonormal basis around the normal (Duff et al. 2017).
  let n = normalize(normal);
  let sign_z = select(-1.0, 1.0, n.z >= 0.0);
  let a = -1.0 / (sign_z + n.z);
  let b = n.x * n.y * a;
  let tangent = vec3f(1.0 + sign_z * n.x * n.x * a, sign_z * b, -sign_z * n.x);
  let bitangent = vec3f(b, sign_z + n.y * n.y * a, -n.y);
  let circumradius = radius * {{disk_circumradius_scale}};
  let u = transform * (tangent * circumradius);
  let v = transform * (bitangent * circumradius);
  let o = transform * (centre - P);
  var polygon = matc_ltc_polygon_start();
  let first_vertex = o + u;
  var previous = first_vertex;
  for (var i = 1; i < {{disk_sides}}; i++) {
    let angle = f32(i) * {{disk_angle_step}};
    let current = o + cos(angle) * u + sin(angle) * v;
    matc_ltc_add_edge(&polygon, previous, current);
    previous = current;
  }
  matc_ltc_add_edge(&polygon, previous, first_vertex);
  return polygon;
}

fn matc_ltc_disk_integral(transform: mat3x3f, P: vec3f, centre: vec3f, normal: vec3f,
                          radius: f32) -> f32 {
  return matc_ltc_polygon_result(matc_ltc_disk_polygon(transform, P, centre, normal, radius));
}

// A sphere light (centre, radius; P outside it): the disk at its centre facing P that fills the
// same cone of directions, radius * d / sqrt(d^2 - radius^2) for the distance d.
fn matc_ltc_sphere_polygon(transform: mat3x3f, P: vec3f, centre: vec3f,
                           radius: f32) -> MatcLtcPolygon {
  let towards = P - centre;
  let d2 = dot(towards, towards);
  let disk_radius = radius * sqrt(d2 / max(d2 - radius * radius, 1e-30));
  return matc_ltc_disk_polygon(transform, P, centre, towards, disk_radius);
}

fn matc_ltc_sphere_integral(transform: mat3x3f, P: vec3f, centre: vec3f, radius: f32) -> f32 {
  return matc_ltc_polygon_result(matc_ltc_sphere_polygon(transform, P, centre, radius));
}

// The GGX lobe without Fresnel, f cos (height-correlated Smith), at a unit L in the shading
// frame (V in the xz-plane at NdotV): what the LTC approximates.
fn matc_ltc_ggx_lobe(NdotV: f32, roughness: f32, L: vec3f) -> f32 {
  let nv = clamp(NdotV, 1e-3, 1.0);
  let alpha = max(roughness * roughness, 1e-4);
  let a2 = alpha * alpha;
  let H = normalize(vec3f(sqrt(1.0 - nv * nv), 0.0, nv) + L);
  // 1 - H.z * H.z as H.x * H.x + H.y * H.y: float32 loses the difference near the peak.
  let d = H.x * H.x + H.y * H.y + H.z * H.z * a2;
  let D = a2 / (3.14159265358979 * d * d);
  let nl = L.z;
  let smith =
      0.5 / (nl * sqrt(nv * nv * (1.0 - a2) + a2) + nv * sqrt(nl * nl * (1.0 - a2) + a2));
  return select(0.0, D * smith * nl, nl > 0.0);
}

// The quality level's geometry for a polygon (docs/ltc.md): (I', V.H, I). Where the light lies on
// the lobe is the direction L of the vector form factor f taken back through M (the adjugate of
// M^-1; ad - bc > 0 in every texel). I' = I mix(r, 1, s): r, the lobe's f cos over albedo times
// the LTC's density at L (u.z |adj u|^3 / (pi det^2) for u = f / |f|), clamped to [0, 4]; s =
// q (2 - q) for q = sqrt(|f|), from the light's size. V.H = sqrt((1 + V.L) / 2).
fn matc_ltc_following_geometry(polygon: MatcLtcPolygon, ltc: vec4f, NdotV: f32, roughness: f32,
                               albedo: f32) -> vec3f {
  let sum = matc_ltc_polygon_sum(polygon) * 0.15915494309189535;  // 1 / (2 pi)
  let f = select(sum, -sum, sum.z < 0.0);
  let length_f = length(f);
  let u = f / max(length_f, 1e-30);
  let det = ltc.x * ltc.w - ltc.y * ltc.z;
  let back = vec3f(ltc.w * u.x - ltc.y * u.z, det * u.y, ltc.x * u.z - ltc.z * u.x);
  let back_length = length(back);
  let L = back / max(back_length, 1e-30);
  let ndotv = clamp(NdotV, 0.0, 1.0);
  let V = vec3f(sqrt(1.0 - ndotv * ndotv), 0.0, ndotv);
  let vdoth = sqrt(clamp(0.5 + 0.5 * dot(V, L), 0.0, 1.0));
  let ratio = clamp(matc_ltc_ggx_lobe(NdotV, roughness, L) * 3.14159265358979 * det * det /
                        max(albedo * u.z * back_length * back_length * back_length, 1e-30),
                    0.0, 4.0);
  let integral = min(f.z, 1.0);
  let root = sqrt(min(length_f, 1.0));
  return vec3f(integral * mix(ratio, 1.0, root * (2.0 - root)), vdoth, integral);
}

// The quality level's radiance: L = I' mix(E F_light, Fbar, I), E = bbar.x the lobe's albedo,
// F_light the Fresnel at V.H = geometry.y and Fbar the preintegrated Fresnel: a light over a small
// part of the lobe sees the Fresnel where it lies, one over all of it the lobe's average.
fn matc_ltc_following_radiance(geometry: vec3f, bbar: vec4f, f_light: vec3f,
                               fbar: vec3f) -> vec3f {
  return geometry.x * mix(bbar.x * f_light, fbar, geometry.z);
}

{{following}}
// Radiance from a quad light of radiance 1: bbar from matc_lut and ltc from matc_ltc, both at
// their texcoords for (NdotV, roughness).
fn matc_ltc_quad_light(c: MatcFresnelCoefficients, bbar: vec4f, ltc: vec4f, N: vec3f, V: vec3f,
                       P: vec3f, q0: vec3f, q1: vec3f, q2: vec3f, q3: vec3f) -> vec3f {
  return matc_ltc_quad_integral(matc_ltc_transform(N, V, ltc), P, q0, q1, q2, q3) *
         matc_fresnel_preintegrated(c, bbar);
}

// ... and from a disk light of radiance 1.
fn matc_ltc_disk_light(c: MatcFresnelCoefficients, bbar: vec4f, ltc: vec4f, N: vec3f, V: vec3f,
                       P: vec3f, centre: vec3f, normal: vec3f, radius: f32) -> vec3f {
  return matc_ltc_disk_integral(matc_ltc_transform(N, V, ltc), P, centre, normal, radius) *
         matc_fresnel_preintegrated(c, bbar);
}

// ... and from a sphere light of radiance 1.
fn matc_ltc_sphere_light(c: MatcFresnelCoefficients, bbar: vec4f, ltc: vec4f, N: vec3f, V: vec3f,
                         P: vec3f, centre: vec3f, radius: f32) -> vec3f {
  return matc_ltc_sphere_integral(matc_ltc_transform(N, V, ltc), P, centre, radius) *
         matc_fresnel_preintegrated(c, bbar);
}

{{following_lights}}