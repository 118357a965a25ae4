// matc {{version}}: the Fresnel decomposition of Belcour, Bati and Barla (SIGGRAPH 2020),
// F(mu) = sum_i c_i b_i(mu). Generated (inputs {{inputs_hash}}); do not edit, rerun matc.
// GLSL 3.30+, GLSL ES 3.00+ and Vulkan GLSL; every name starts with matc_ / Matc / MATC_.
#ifndef MATC_FRESNEL_GLSL
#define MATC_FRESNEL_GLSL

// Material snippets check this to refuse a library from another matc version.
#define MATC_VERSION {{version_number}}
// Width and height of the preintegrated table this build wrote (matc_lut.*).
#define MATC_LUT_SIZE {{lut_size}}

// A material's coefficients c_0..c_3, one row per colour channel. 48 bytes with std140 and
// std430 layouts, so it can sit in a uniform or storage buffer as is.
struct MatcFresnelCoefficients {
  vec4 red;
  vec4 green;
  vec4 blue;
};

// sum_i c_i v_i per channel; matc_combine clamps it at 0, where a truncated basis dips below it.
vec3 matc_combine_sum(MatcFresnelCoefficients c, vec4 v) {
  return vec3(dot(c.red, v), dot(c.green, v), dot(c.blue, v));
}
vec3 matc_combine(MatcFresnelCoefficients c, vec4 v) {
  return max(matc_combine_sum(c, v), vec3(0.0));
}

{{basis_function}}
{{lut_texcoord}}
// The preintegrated Fresnel from the table's texel bbar at matc_lut_texcoord(NdotV, roughness):
// sum_i c_i bbar_i, written with c_1 = 1 - c_0 (which every coefficient source sets) as
// bbar_1 + c_0 (bbar_0 - bbar_1) + c_2 bbar_2 + c_3 bbar_3, three multiply-adds a channel.
// Without the clamp at 0, for curves matc proved non-negative (docs/shaders.md).
vec3 matc_fresnel_preintegrated_sum(MatcFresnelCoefficients c, vec4 bbar) {
  vec3 c0 = vec3(c.red.x, c.green.x, c.blue.x);
  vec3 c2 = vec3(c.red.z, c.green.z, c.blue.z);
  vec3 c3 = vec3(c.red.w, c.green.w, c.blue.w);
  return bbar.y + c0 * (bbar.x - bbar.y) + c2 * bbar.z + c3 * bbar.w;
}
// Clamped at 0, where a truncated curve dips below it: what every coefficient source may use.
vec3 matc_fresnel_preintegrated(MatcFresnelCoefficients c, vec4 bbar) {
  return max(matc_fresnel_preintegrated_sum(c, bbar), vec3(0.0));
}

// Turquin (2019)'s multiple-scattering scale for the specular lobe, 1 + F0 (1 - E) / E, with
// E = bbar.x the directional albedo of the GGX lobe (F = 1).
vec3 matc_energy_compensation(MatcFresnelCoefficients c, vec4 bbar) {
  vec3 f0 = vec3(c.red.x, c.green.x, c.blue.x);
  float albedo = max(bbar.x, 1e-4);  // guards the NdotV = 0 column
  return vec3(1.0) + f0 * ((1.0 - albedo) / albedo);
}
// glTF's metal-rough model per pixel (docs/gltf.md): glTF's BRDF mixes its dielectric and metal
// BRDFs by metalness (metallicFactor times the metallic-roughness texture's blue channel); matc's
// Fresnel replaces the metal's only. `dielectric` and `metal` are the same term of each lobe (F for
// a light, each with its own multiple-scattering scale; the preintegrated F for image light).
vec3 matc_metal_rough(vec3 dielectric, vec3 metal, float metalness) {
  return mix(dielectric, metal, clamp(metalness, 0.0, 1.0));
}
// glTF's dielectric Fresnel, Schlick's curve from f0 to f90 (f0 0.04 and f90 1 at glTF's index
// 1.5; KHR_materials_ior and KHR_materials_specular change both), for an engine without its own.
vec3 matc_dielectric_fresnel(vec3 f0, vec3 f90, float VdotH) {
  float m = clamp(1.0 - VdotH, 0.0, 1.0);
  float m2 = m * m;
  return f0 + (f90 - f0) * (m2 * m2 * m);
}

// ---- Metals under a thin film: their own table (docs/thin-film.md). ----
// A filmed metal's <name>.film.<ext>, 65 x 18 texels: row 0 F over sqrt(mu), rows 1-17 the
// preintegrated F over sqrt(NdotV) and sqrt((roughness - 0.05) / 0.95), texel centres on the
// nodes. Sample it as the preintegrated table (linear, clamp to edge) at these coordinates; its
// rgb is F (or Fbar) itself.
vec2 matc_film_fresnel_texcoord(float mu) {
  return vec2(sqrt(clamp(mu, 0.0, 1.0)) * (64.0 / 65.0) + 0.5 / 65.0, 0.5 / 18.0);
}
vec2 matc_film_preintegrated_texcoord(float NdotV, float roughness) {
  float x = sqrt(clamp(NdotV, 0.0, 1.0));
  float y = sqrt(clamp((roughness - 0.05) * (1.0 / 0.95), 0.0, 1.0));
  return vec2(x * (64.0 / 65.0) + 0.5 / 65.0, y * (16.0 / 18.0) + 1.5 / 18.0);
}
// The fetches: TABLE is a sampler2D expression (in Vulkan GLSL sampler2D(texture, sampler), which
// must appear at its point of use, hence macros).
#define MATC_FILM_FRESNEL(TABLE, MU) textureLod(TABLE, matc_film_fresnel_texcoord(MU), 0.0)
#define MATC_FILM_PREINTEGRATED(TABLE, NDOTV, ROUGHNESS) textureLod(TABLE, matc_film_preintegrated_texcoord((NDOTV), (ROUGHNESS)), 0.0)
// A thickness per pixel (docs/thin-film.md "A thickness per pixel"): <name>.film.<ext> stacks the
// tables of `slices` films uniform over the material's thickness range, 65 x 18 slices texels:
// rows 0 to slices - 1 F, then for each roughness node j the slices rows of Fbar. `thickness` is
// the coordinate in [0, 1] over the range (a thickness texture's green channel, as glTF's
// iridescenceThicknessTexture); matc_film_thickness_<name> maps nanometres to it. A light is one
// fetch, over (sqrt(mu), thickness); image light two, at the roughness nodes either side, mixed.
// Where along the thickness axis a read lands, in texels: held 1/1024 of a slice inside the end
// slices, since in a texture thousands of rows tall a float texcoord on the last slice's texel
// centre can land past it, in the next block (the CPU runtime holds it so too).
float matc_film_stack_slice(float thickness, float slices) {
  float last = slices - 1.0;
  return clamp(clamp(thickness, 0.0, 1.0) * last, 1.0 / 1024.0, last - 1.0 / 1024.0) + 0.5;
}
vec2 matc_film_stack_fresnel_texcoord(float mu, float thickness, float slices) {
  float s = matc_film_stack_slice(thickness, slices);
  return vec2(sqrt(clamp(mu, 0.0, 1.0)) * (64.0 / 65.0) + 0.5 / 65.0, s / (18.0 * slices));
}
// xy and xz: the texcoords at the roughness nodes below and above; w: the weight of the one above.
vec4 matc_film_stack_preintegrated_texcoords(float NdotV, float roughness, float thickness,
                                             float slices) {
  float x = sqrt(clamp(NdotV, 0.0, 1.0)) * (64.0 / 65.0) + 0.5 / 65.0;
  float r = sqrt(clamp((roughness - 0.05) * (1.0 / 0.95), 0.0, 1.0)) * 16.0;
  float j = min(floor(r), 15.0);
  float s = matc_film_stack_slice(thickness, slices);
  float height = 18.0 * slices;
  return vec4(x, (slices * (1.0 + j) + s) / height, (slices * (2.0 + j) + s) / height, r - j);
}
#define MATC_FILM_STACK_FRESNEL(TABLE, MU, THICKNESS, SLICES) textureLod(TABLE, matc_film_stack_fresnel_texcoord((MU), (THICKNESS), (SLICES)), 0.0)
// COORDS: matc_film_stack_preintegrated_texcoords(NdotV, roughness, thickness, slices).
#define MATC_FILM_STACK_PREINTEGRATED(TABLE, COORDS) mix(textureLod(TABLE, (COORDS).xy, 0.0), textureLod(TABLE, (COORDS).xz, 0.0), (COORDS).w)
{{coefficient_table}}
{{area_lights}}
{{analytic_lut}}
{{basis_layers}}{{embedded_lut}}
#endif  // MATC_FRESNEL_GLSL
