// The scene the engine integrations are judged on (docs/web-engines.md): a unit sphere seen by a
// perspective camera under an environment map, a point light and a rect area light, and the
// project's Monte-Carlo reference of it, a GLSL ES 3.00 fragment shader that engines can run as a
// plain shader material: single-scattering GGX (alpha = roughness^2, height-correlated Smith)
// with the material's *exact* Fresnel curve (tabulated at 1024 cosines), the environment by
// visible-normal sampling (Heitz 2018), the rect light by stratified area sampling and the same
// visible-normal samples combined by multiple importance sampling (the balance heuristic: area
// samples alone sparkle on a sharp lobe, a coat's), the point light in closed form; times Turquin's multiple-scattering factor 1 + F0 (1 - E) / E (E the
// lobe's directional albedo, channel 0 of matc's table), which both engine materials apply to
// their punctual and image lighting. A coated metal is two such lobes (coating.md): the base's
// at its roughness with the exact layered base curve at v.h (the multiple-scattering factor with
// that curve's F0), plus the coat's at the coat's roughness with its weight times the coat's
// exact Fresnel at v.h (`matc eval`'s F_exact_base and F_exact_coat).

// The rect light's radiance is a whole number: Babylon.js's stock area-light Fresnel mixes the
// light's colour into its weights (computeAreaSpecularLighting), which only works for colours up
// to 1, so its page draws that many coincident lights of radiance 1.
export const kScene = {
  size: 128,  // pixels, square
  camera: { position: [0, 0, 3.2], fov: 40, near: 0.1, far: 20 },
  point: { position: [2.0, 2.2, 2.5], intensity: 10 },
  rect: { position: [-2.2, 0.4, -0.8], width: 2.0, height: 1.4, intensity: 3 },
  environment: { width: 256, height: 128, intensity: 1 },
  samples: { environment: 1024, rectSide: 16 },
  fresnelSamples: 1024,
};

// The environment: a sky that brightens towards the zenith, a darker ground, and two soft
// sources: one high in front (camera side) and one behind the sphere, which the rim reflects at
// grazing angles. Radiance in direction d (unit); stringified into pages, so self-contained.
export function environmentRadiance(d) {
  const lobe = (centre, sharpness, colour) => {
    const c = Math.hypot(...centre);
    const cosine = (d[0] * centre[0] + d[1] * centre[1] + d[2] * centre[2]) / c;
    const w = Math.exp(sharpness * (cosine - 1));
    return colour.map((x) => x * w);
  };
  const y = d[1];
  const sky = y > 0 ? [0.35 + 0.5 * y, 0.45 + 0.45 * y, 0.6 + 0.4 * y] : [0.18, 0.15, 0.12];
  const front = lobe([0.6, 0.7, 1.0], 18, [5.0, 4.6, 4.0]);
  const behind = lobe([-0.3, 0.15, -1.0], 10, [3.0, 3.2, 3.6]);
  return [0, 1, 2].map((c) => sky[c] + front[c] + behind[c]);
}

// The environment as an equirectangular texture as three.js maps it: u = atan(z, x) / 2pi + 0.5,
// v = asin(y) / pi + 0.5, row 0 at v = 0 (straight down).
export function environmentTexels(width, height, intensity = 1) {
  const texels = new Float32Array(width * height * 4);
  for (let j = 0; j < height; ++j) {
    const y = Math.sin(((j + 0.5) / height - 0.5) * Math.PI);
    const ring = Math.sqrt(Math.max(0, 1 - y * y));
    for (let i = 0; i < width; ++i) {
      const phi = ((i + 0.5) / width - 0.5) * 2 * Math.PI;
      const radiance = environmentRadiance([ring * Math.cos(phi), y, ring * Math.sin(phi)]);
      texels.set([...radiance.map((x) => x * intensity), 1], 4 * (j * width + i));
    }
  }
  return texels;
}

// The environment as the six faces of a cube map (+x, -x, +y, -y, +z, -z, OpenGL's directions
// per texel), each size x size RGBA floats, with z mirrored (flipZ) for engines that look their
// cube maps up with -z (Babylon.js in a right-handed scene).
export function environmentCubeFaces(size, intensity = 1, flipZ = false) {
  const direction = [(s, t) => [1, -t, -s], (s, t) => [-1, -t, s], (s, t) => [s, 1, t],
                     (s, t) => [s, -1, -t], (s, t) => [s, -t, 1], (s, t) => [-s, -t, -1]];
  return direction.map((at) => {
    const face = new Float32Array(size * size * 4);
    for (let j = 0; j < size; ++j) {
      for (let i = 0; i < size; ++i) {
        const g = at((2 * (i + 0.5)) / size - 1, (2 * (j + 0.5)) / size - 1);
        const l = Math.hypot(...g);
        const d = [g[0] / l, g[1] / l, (flipZ ? -g[2] : g[2]) / l];
        face.set([...environmentRadiance(d).map((x) => x * intensity), 1], 4 * (j * size + i));
      }
    }
    return face;
  });
}

// The rect light's corners, as three.js puts them for a light at `position` looking at the
// origin (its -z), halfWidth along its local x and halfHeight along its local y; and its normal
// (the side it lights).
export function rectLightGeometry({ position, width, height }) {
  const norm = (a) => { const l = Math.hypot(...a); return a.map((x) => x / l); };
  const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
  const z = norm(position);
  const x = norm(cross([0, 1, 0], z));
  const y = cross(z, x);
  const at = (s, t) => position.map((p, i) => p + s * x[i] * width / 2 + t * y[i] * height / 2);
  return { corners: [at(1, -1), at(-1, -1), at(-1, 1), at(1, 1)], normal: z.map((v) => -v),
           origin: at(-1, -1), edgeU: x.map((v) => v * width), edgeV: y.map((v) => v * height) };
}

export const kReferenceVertexShader = `
out vec3 reference_position;
out vec3 reference_normal;
out vec2 reference_uv;
void main() {
  reference_uv = uv;
  vec4 world = modelMatrix * vec4(position, 1.0);
  reference_position = world.xyz;
  reference_normal = normalize(mat3(modelMatrix) * normal);
  gl_Position = projectionMatrix * viewMatrix * world;
}`;

// Writes linear radiance in rgb and 1 + NdotV in alpha (0 where nothing was drawn), so that the
// test can split pixels into regions by viewing angle. `cameraPosition` is three.js's built-in.
export const kReferenceFragmentShader = `
precision highp float;
precision highp sampler2D;
#ifdef REFERENCE_CUBE_ENVIRONMENT
uniform samplerCube reference_environment;  // looked up with -z, as Babylon.js does in a right-handed scene
#else
uniform sampler2D reference_environment;  // equirectangular, linear filtering
#endif
// Exact F(mu), mu = i / (n - 1), n texels in a row: row 0 the metal's (a coated metal's base
// lobe's), row 1 a coated metal's coat lobe's (reference_coated = 1), weight included.
uniform sampler2D reference_fresnel;
uniform int reference_coated;
uniform float reference_coat_roughness;
// A textured metal instead (reference_textured = 1): Gulbrandsen's reflectivity and edge tint
// per pixel from these maps (linear values), the exact conductor Fresnel of their n + ik.
uniform int reference_textured;
uniform sampler2D reference_reflectivity_map;
uniform sampler2D reference_edge_tint_map;
uniform sampler2D reference_albedo;       // matc_lut: E = channel 0
uniform float reference_roughness;
uniform vec3 reference_f0;
uniform vec3 reference_point_position;
uniform float reference_point_intensity;
uniform vec3 reference_rect_origin;
uniform vec3 reference_rect_u;
uniform vec3 reference_rect_v;
uniform vec3 reference_rect_normal;
uniform float reference_rect_intensity;
uniform int reference_environment_samples;
uniform int reference_rect_side;
uniform float reference_lut_size;    // a layer's width and height (the table's height)
uniform float reference_lut_layers;  // layers side by side (a default build: a basis each)
in vec3 reference_position;
in vec3 reference_normal;
in vec2 reference_uv;
#ifdef REFERENCE_GL_FRAG_COLOR
#define reference_color gl_FragColor  // engines that declare the output themselves (Babylon.js)
#else
out vec4 reference_color;
#endif
const float PI = 3.14159265358979;

vec3 pixel_n;  // the textured metal's index of refraction at this pixel
vec3 pixel_k;
// Unpolarised Fresnel reflectance of a conductor n + ik at cos(theta) = mu.
vec3 conductor_fresnel(vec3 n, vec3 k, float mu) {
  float c = clamp(mu, 1e-6, 1.0), c2 = c * c, s2 = 1.0 - c2;
  vec3 t0 = n * n - k * k - s2;
  vec3 a2b2 = sqrt(t0 * t0 + 4.0 * n * n * k * k);
  vec3 a = sqrt(max(0.5 * (a2b2 + t0), 0.0));
  vec3 rs = (a2b2 - 2.0 * a * c + c2) / (a2b2 + 2.0 * a * c + c2);
  vec3 rp = rs * (c2 * a2b2 - 2.0 * a * c * s2 + s2 * s2) / (c2 * a2b2 + 2.0 * a * c * s2 + s2 * s2);
  return 0.5 * (rs + rp);
}
// lobe 0: the metal (or a coated metal's base), 1: the coat.
vec3 exact_fresnel(float mu, int lobe) {
  if (reference_textured == 1) return conductor_fresnel(pixel_n, pixel_k, mu);
  float n = float(textureSize(reference_fresnel, 0).x);
  float row = lobe == 0 ? 0.25 : 0.75;
  return texture(reference_fresnel, vec2(clamp(mu, 0.0, 1.0) * (n - 1.0) / n + 0.5 / n, row)).rgb;
}
float smith_lambda(float a2, float cosine) {
  float c2 = max(cosine * cosine, 1e-8);
  return 0.5 * (sqrt(1.0 + a2 * (1.0 - c2) / c2) - 1.0);
}
// f(l, v) cos(l) for unit l, v in the shading frame of normal n.
vec3 brdf_cosine(vec3 n, vec3 v, vec3 l, float a2, int lobe) {
  float nl = dot(n, l), nv = dot(n, v);
  if (nl <= 0.0 || nv <= 0.0) return vec3(0.0);
  vec3 h = normalize(l + v);
  float nh = dot(n, h);
  float d = a2 / (PI * pow(nh * nh * (a2 - 1.0) + 1.0, 2.0));
  float g2 = 1.0 / (1.0 + smith_lambda(a2, nv) + smith_lambda(a2, nl));
  return exact_fresnel(dot(v, h), lobe) * (d * g2 / (4.0 * nv));
}
vec3 environment(vec3 d) {
#ifdef REFERENCE_CUBE_ENVIRONMENT
  return textureLod(reference_environment, vec3(d.x, d.y, -d.z), 0.0).rgb;
#else
  vec2 uv = vec2(atan(d.z, d.x) / (2.0 * PI) + 0.5, asin(clamp(d.y, -1.0, 1.0)) / PI + 0.5);
  return textureLod(reference_environment, uv, 0.0).rgb;
#endif
}
float radical_inverse(uint bits) {
  bits = (bits << 16u) | (bits >> 16u);
  bits = ((bits & 0x55555555u) << 1u) | ((bits & 0xAAAAAAAAu) >> 1u);
  bits = ((bits & 0x33333333u) << 2u) | ((bits & 0xCCCCCCCCu) >> 2u);
  bits = ((bits & 0x0F0F0F0Fu) << 4u) | ((bits & 0xF0F0F0F0u) >> 4u);
  bits = ((bits & 0x00FF00FFu) << 8u) | ((bits & 0xFF00FF00u) >> 8u);
  return float(bits) * 2.3283064365386963e-10;
}
vec2 pixel_shift() {  // Cranley-Patterson rotation per pixel, from a hash of its coordinates
  uvec2 p = uvec2(gl_FragCoord.xy);
  uint h = p.x * 1973u + p.y * 9277u + 26699u;
  h = (h ^ 61u) ^ (h >> 16u); h *= 9u; h = h ^ (h >> 4u); h *= 0x27d4eb2du; h = h ^ (h >> 15u);
  uint k = h * 747796405u + 2891336453u;
  return vec2(float(h & 0xffffu), float(k >> 16u)) / 65536.0;
}
// Heitz 2018: a visible normal of the GGX lobe for the view ve in the local frame (z = normal).
vec3 sample_vndf(vec3 ve, float alpha, vec2 u) {
  vec3 vh = normalize(vec3(alpha * ve.x, alpha * ve.y, ve.z));
  float lensq = vh.x * vh.x + vh.y * vh.y;
  vec3 t1 = lensq > 0.0 ? vec3(-vh.y, vh.x, 0.0) * inversesqrt(lensq) : vec3(1.0, 0.0, 0.0);
  vec3 t2 = cross(vh, t1);
  float r = sqrt(u.x);
  float phi = 2.0 * PI * u.y;
  float p1 = r * cos(phi);
  float p2 = r * sin(phi);
  float s = 0.5 * (1.0 + vh.z);
  p2 = (1.0 - s) * sqrt(1.0 - p1 * p1) + s * p2;
  vec3 nh = p1 * t1 + p2 * t2 + sqrt(max(0.0, 1.0 - p1 * p1 - p2 * p2)) * vh;
  return normalize(vec3(alpha * nh.x, alpha * nh.y, max(0.0, nh.z)));
}
// The roughness a lobe shades with: the material's, or (REFERENCE_GEOMETRY_ROUGHNESS) the one
// three.js shades with: at least 0.045, widened by the normal's screen-space derivative (its
// specular anti-aliasing, for the base and the coat alike), so that the reference judges the
// Fresnel alone.
float shading_roughness(float roughness) {
#ifdef REFERENCE_GEOMETRY_ROUGHNESS
  vec3 view_normal = normalize(mat3(viewMatrix) * reference_normal);
  vec3 dxy = max(abs(dFdx(view_normal)), abs(dFdy(view_normal)));
  return min(max(roughness, 0.045) + max(max(dxy.x, dxy.y), dxy.z), 1.0);
#else
  return roughness;
#endif
}
// Where the ray from the shaded point along l meets the rect light's front: its squared distance,
// or 0 where it misses.
float rect_hit(vec3 l) {
  float facing = -dot(l, reference_rect_normal);
  if (facing <= 0.0) return 0.0;
  float t = dot(reference_position - reference_rect_origin, reference_rect_normal) / facing;
  if (t <= 0.0) return 0.0;
  vec3 q = reference_position + t * l - reference_rect_origin;
  float s = dot(q, reference_rect_u) / dot(reference_rect_u, reference_rect_u);
  float r = dot(q, reference_rect_v) / dot(reference_rect_v, reference_rect_v);
  return s >= 0.0 && s <= 1.0 && r >= 0.0 && r <= 1.0 ? t * t : 0.0;
}
// The rect light's radiance towards v along l (a direction that meets it at squared distance d2),
// as one of the rect's samples: f cos L / (the environment's count times the visible-normal pdf +
// the rect's count times the area pdf), each pdf per solid angle; so a direction either strategy
// drew adds this, and their sum over both strategies' samples is the balance heuristic's estimate.
vec3 rect_sample(vec3 n, vec3 v, vec3 l, float d2, float a2, int lobe) {
  float nv = dot(n, v);
  vec3 h = normalize(l + v);
  float nh = dot(n, h);
  float d = a2 / (PI * pow(nh * nh * (a2 - 1.0) + 1.0, 2.0));
  float visible_normal_pdf = d / (4.0 * nv * (1.0 + smith_lambda(a2, nv)));
  float facing = -dot(l, reference_rect_normal);
  float area = length(cross(reference_rect_u, reference_rect_v));
  float area_pdf = d2 / (area * facing);
  float strategies = float(reference_environment_samples) * visible_normal_pdf +
                     float(reference_rect_side * reference_rect_side) * area_pdf;
  return brdf_cosine(n, v, l, a2, lobe) * (reference_rect_intensity / strategies);
}
// One lobe's radiance towards v under the three lights, its exact curve at v.h.
vec3 lobe_radiance(vec3 n, vec3 v, float roughness, int lobe, vec2 shift) {
  float nv = dot(n, v);
  float alpha = roughness * roughness;
  float a2 = alpha * alpha;
  vec3 rect = vec3(0.0);
  // Environment: VNDF samples, weight F(v.h) G2 / G1(v).
  vec3 t = normalize(abs(n.y) < 0.999 ? cross(vec3(0.0, 1.0, 0.0), n) : cross(vec3(1.0, 0.0, 0.0), n));
  vec3 b = cross(n, t);
  vec3 ve = vec3(dot(v, t), dot(v, b), nv);
  vec3 image = vec3(0.0);
  int count = reference_environment_samples;
  for (int i = 0; i < count; ++i) {
    vec2 u = fract(vec2((float(i) + 0.5) / float(count), radical_inverse(uint(i))) + shift);
    vec3 h = sample_vndf(ve, alpha, u);
    vec3 le = reflect(-ve, h);
    if (le.z <= 0.0) continue;
    float g1 = 1.0 / (1.0 + smith_lambda(a2, nv));
    float g2 = 1.0 / (1.0 + smith_lambda(a2, nv) + smith_lambda(a2, le.z));
    vec3 l = le.x * t + le.y * b + le.z * n;
    image += environment(l) * exact_fresnel(dot(ve, h), lobe) * (g2 / g1);
    float hit = rect_hit(l);
    if (hit > 0.0) rect += rect_sample(n, v, l, hit, a2, lobe);
  }
  image /= float(count);
  // Point light: closed form, as three.js attenuates it (1 / d^2).
  vec3 to_point = reference_point_position - reference_position;
  float d2 = dot(to_point, to_point);
  vec3 point = brdf_cosine(n, v, normalize(to_point), a2, lobe) * (reference_point_intensity / d2);
  // Rect light: stratified area samples, one-sided (and the visible-normal samples above).
  int side = reference_rect_side;
  for (int i = 0; i < side; ++i) {
    for (int j = 0; j < side; ++j) {
      vec2 st = (vec2(i, j) + shift) / float(side);  // jittered strata
      vec3 p = reference_rect_origin + st.x * reference_rect_u + st.y * reference_rect_v;
      vec3 to_light = p - reference_position;
      float dl2 = dot(to_light, to_light);
      vec3 l = to_light * inversesqrt(dl2);
      if (-dot(l, reference_rect_normal) <= 0.0) continue;
      rect += rect_sample(n, v, l, dl2, a2, lobe);
    }
  }
  return image + point + rect;
}
void main() {
  vec3 f0 = reference_f0;
  if (reference_textured == 1) {
    // Gulbrandsen (2014): n between n_min(r) (g = 1) and n_max(r) (g = 0), then k from r.
    vec3 r = clamp(texture(reference_reflectivity_map, reference_uv).rgb, 0.0, 0.999);
    vec3 g = clamp(texture(reference_edge_tint_map, reference_uv).rgb, 0.0, 1.0);
    vec3 sqrt_r = sqrt(r);
    pixel_n = g * (1.0 - r) / (1.0 + r) + (1.0 - g) * (1.0 + sqrt_r) / (1.0 - sqrt_r);
    pixel_k = sqrt(max(((pixel_n + 1.0) * (pixel_n + 1.0) * r - (pixel_n - 1.0) * (pixel_n - 1.0)) / (1.0 - r), 0.0));
    f0 = r;
  }
  vec3 n = normalize(reference_normal);
  vec3 v = normalize(cameraPosition - reference_position);
  float nv = dot(n, v);
  if (nv <= 0.0) { reference_color = vec4(0.0, 0.0, 0.0, 1.0); return; }
  // Both derivatives taken here, outside the lobes' branches.
  float roughness = shading_roughness(reference_roughness);
  float coat_roughness = shading_roughness(reference_coat_roughness);
  vec2 shift = pixel_shift();
  vec3 base = lobe_radiance(n, v, roughness, 0, shift);
  // Turquin's multiple scattering of the (base) lobe, as the engine materials apply it.
  // E is the same in every layer (b_0 = 1): the first layer's.
  float size = reference_lut_size;
  vec2 lut_uv = vec2(sqrt(clamp(nv, 0.0, 1.0)), roughness) * ((size - 1.0) / size) + 0.5 / size;
  lut_uv.x /= reference_lut_layers;
  float e = max(texture(reference_albedo, lut_uv).x, 1e-4);
  vec3 compensation = 1.0 + f0 * (1.0 - e) / e;
  vec3 coat = reference_coated == 1 ? lobe_radiance(n, v, coat_roughness, 1, shift) : vec3(0.0);
  reference_color = vec4(base * compensation + coat, 1.0 + nv);
}`;

// The scene with only one of its light paths ("environment", "point", "rect"), or all ("all").
export function sceneWith(lights) {
  if (lights === "all") return kScene;
  return { ...kScene,
           environment: { ...kScene.environment, intensity: lights === "environment" ? 1 : 0 },
           point: { ...kScene.point, intensity: lights === "point" ? kScene.point.intensity : 0 },
           rect: { ...kScene.rect, intensity: lights === "rect" ? kScene.rect.intensity : 0 } };
}
