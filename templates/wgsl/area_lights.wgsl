
// ---- Area lights: linearly transformed cosines (Heitz, Dupuy, Hill, Neubelt 2016) ----
// L = I_ltc(light) * matc_fresnel_preintegrated(c, bbar): the LTC table (matc_ltc.*) gives the
// lobe's shape, the preintegrated table its magnitude and Fresnel (docs/ltc.md). Lights are
// two-sided with radiance 1: scale by the light's radiance. The LTC table is always f32: sampling
// it with a linear filter needs the device feature "float32-filterable".

// Width and height of the LTC table this build wrote (matc_ltc.*).
const MATC_LTC_SIZE: i32 = {{ltc_size}};

// Where to sample the LTC table: the preintegrated table's axes, at the LTC table's size.
fn matc_ltc_texcoord(NdotV: f32, roughness: f32) -> vec2f {
  let axes = vec2f(sqrt(clamp(NdotV, 0.0, 1.0)), clamp(roughness, 0.0, 1.0));
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
struct MatcLtcPolygon {
  sum: f32,
  exit_point: vec3f,
  entry_point: vec3f,
  exits: bool,
  enters: bool,
}

fn matc_ltc_polygon_start() -> MatcLtcPolygon {
  return MatcLtcPolygon(0.0, vec3f(0.0), vec3f(0.0), false, false);
}

// theta * normalize(a x b).z for unit vectors a, b (atan2 stays accurate for short arcs).
fn matc_ltc_edge(a: vec3f, b: vec3f) -> f32 {
  let n = cross(a, b);
  let s = length(n);
  if (s > 0.0) {
    return n.z * (atan2(s, dot(a, b)) / s);
  }
  return 0.0;
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

fn matc_ltc_polygon_result(polygon: MatcLtcPolygon) -> f32 {
  var sum = polygon.sum;
  if (polygon.exits && polygon.enters) {
    sum += matc_ltc_edge(polygon.exit_point, polygon.entry_point);
  }
  return min(abs(sum) * 0.15915494309189535, 1.0);  // 1 / (2 pi)
}

// The LTC's integral over a convex planar quad q0..q3 (world space, either winding) seen from P.
fn matc_ltc_quad_integral(transform: mat3x3f, P: vec3f, q0: vec3f, q1: vec3f, q2: vec3f,
                          q3: vec3f) -> f32 {
  let a = transform * (q0 - P);
  let b = transform * (q1 - P);
  let c = transform * (q2 - P);
  let d = transform * (q3 - P);
  var polygon = matc_ltc_polygon_start();
  matc_ltc_add_edge(&polygon, a, b);
  matc_ltc_add_edge(&polygon, b, c);
  matc_ltc_add_edge(&polygon, c, d);
  matc_ltc_add_edge(&polygon, d, a);
  return matc_ltc_polygon_result(polygon);
}

// A disk light (centre, normal, radius) as a regular {{disk_sides}}-gon of the same area.
fn matc_ltc_disk_integral(transform: mat3x3f, P: vec3f, centre: vec3f, normal: vec3f,
                          radius: f32) -> f32 {
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
  return matc_ltc_polygon_result(polygon);
}

// A sphere light (centre, radius; P outside it): the disk at its centre facing P that fills the
// same cone of directions, radius * d / sqrt(d^2 - radius^2) for the distance d.
fn matc_ltc_sphere_integral(transform: mat3x3f, P: vec3f, centre: vec3f, radius: f32) -> f32 {
  let towards = P - centre;
  let d2 = dot(towards, towards);
  let disk_radius = radius * sqrt(d2 / max(d2 - radius * radius, 1e-30));
  return matc_ltc_disk_integral(transform, P, centre, towards, disk_radius);
}

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
