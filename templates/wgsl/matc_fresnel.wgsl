// matc {{version}}: the Fresnel decomposition of Belcour, Bati and Barla (SIGGRAPH 2020),
// F(mu) = sum_i c_i b_i(mu). Generated (inputs {{inputs_hash}}); do not edit, rerun matc.
// WGSL (WebGPU, wgpu); every name starts with matc_ / Matc / MATC_. WGSL has no #include and no
// include guards: put this file once in the shader module, with any number of material files
// (<name>.wgsl), in any order (module-scope declarations may come after their uses).

// Material files assert (const_assert) that this is the matc version they come from.
const MATC_VERSION: i32 = {{version_number}};
// Width and height of the preintegrated table this build wrote (matc_lut.*).
const MATC_LUT_SIZE: i32 = {{lut_size}};

// A material's coefficients c_0..c_3, one row per colour channel: 48 bytes, a valid uniform and
// storage buffer layout as is.
struct MatcFresnelCoefficients {
  red: vec4f,
  green: vec4f,
  blue: vec4f,
}

// sum_i c_i v_i per channel; matc_combine clamps it at 0, where a truncated basis dips below it.
fn matc_combine_sum(c: MatcFresnelCoefficients, v: vec4f) -> vec3f {
  return vec3f(dot(c.red, v), dot(c.green, v), dot(c.blue, v));
}
fn matc_combine(c: MatcFresnelCoefficients, v: vec4f) -> vec3f {
  return max(matc_combine_sum(c, v), vec3f(0.0));
}

{{basis_function}}
{{lut_texcoord}}
// The preintegrated Fresnel from the table's texel bbar at matc_lut_texcoord(NdotV, roughness):
// sum_i c_i bbar_i, written with c_1 = 1 - c_0 (which every coefficient source sets) as
// bbar_1 + c_0 (bbar_0 - bbar_1) + c_2 bbar_2 + c_3 bbar_3, three multiply-adds a channel.
// Without the clamp at 0, for curves matc proved non-negative (docs/shaders.md).
fn matc_fresnel_preintegrated_sum(c: MatcFresnelCoefficients, bbar: vec4f) -> vec3f {
  let c0 = vec3f(c.red.x, c.green.x, c.blue.x);
  let c2 = vec3f(c.red.z, c.green.z, c.blue.z);
  let c3 = vec3f(c.red.w, c.green.w, c.blue.w);
  return bbar.y + c0 * (bbar.x - bbar.y) + c2 * bbar.z + c3 * bbar.w;
}
// Clamped at 0, where a truncated curve dips below it: what every coefficient source may use.
fn matc_fresnel_preintegrated(c: MatcFresnelCoefficients, bbar: vec4f) -> vec3f {
  return max(matc_fresnel_preintegrated_sum(c, bbar), vec3f(0.0));
}

// Turquin (2019)'s multiple-scattering scale for the specular lobe, 1 + F0 (1 - E) / E, with
// E = bbar.x the directional albedo of the GGX lobe (F = 1).
fn matc_energy_compensation(c: MatcFresnelCoefficients, bbar: vec4f) -> vec3f {
  let f0 = vec3f(c.red.x, c.green.x, c.blue.x);
  let albedo = max(bbar.x, 1e-4);  // guards the NdotV = 0 column
  return vec3f(1.0) + f0 * ((1.0 - albedo) / albedo);
}
// glTF's metal-rough model per pixel (docs/gltf.md): glTF's BRDF mixes its dielectric and metal
// BRDFs by metalness (metallicFactor times the metallic-roughness texture's blue channel); matc's
// Fresnel replaces the metal's only. `dielectric` and `metal` are the same term of each lobe (F for
// a light, each with its own multiple-scattering scale; the preintegrated F for image light).
fn matc_metal_rough(dielectric: vec3f, metal: vec3f, metalness: f32) -> vec3f {
  return mix(dielectric, metal, clamp(metalness, 0.0, 1.0));
}
// glTF's dielectric Fresnel, Schlick's curve from f0 to f90 (f0 0.04 and f90 1 at glTF's index
// 1.5; KHR_materials_ior and KHR_materials_specular change both), for an engine without its own.
fn matc_dielectric_fresnel(f0: vec3f, f90: vec3f, VdotH: f32) -> vec3f {
  let m = clamp(1.0 - VdotH, 0.0, 1.0);
  let m2 = m * m;
  return f0 + (f90 - f0) * (m2 * m2 * m);
}

// ---- Metals under a thin film: their own table (docs/thin-film.md). ----
// A filmed metal's <name>.film.<ext>, 65 x 18 texels: row 0 F over sqrt(mu), rows 1-17 the
// preintegrated F over sqrt(NdotV) and sqrt((roughness - 0.05) / 0.95), texel centres on the
// nodes. Sample it as the preintegrated table (linear, clamp to edge) at these coordinates; its
// rgb is F (or Fbar) itself. An rgba32float table needs the device feature "float32-filterable".
fn matc_film_fresnel_texcoord(mu: f32) -> vec2f {
  return vec2f(sqrt(clamp(mu, 0.0, 1.0)) * (64.0 / 65.0) + 0.5 / 65.0, 0.5 / 18.0);
}
fn matc_film_preintegrated_texcoord(NdotV: f32, roughness: f32) -> vec2f {
  let x = sqrt(clamp(NdotV, 0.0, 1.0));
  let y = sqrt(clamp((roughness - 0.05) * (1.0 / 0.95), 0.0, 1.0));
  return vec2f(x * (64.0 / 65.0) + 0.5 / 65.0, y * (16.0 / 18.0) + 1.5 / 18.0);
}
// The fetches (GLSL's MATC_FILM_FRESNEL and MATC_FILM_PREINTEGRATED).
fn matc_film_fresnel(table: texture_2d<f32>, table_sampler: sampler, mu: f32) -> vec4f {
  return textureSampleLevel(table, table_sampler, matc_film_fresnel_texcoord(mu), 0.0);
}
fn matc_film_preintegrated(table: texture_2d<f32>, table_sampler: sampler, NdotV: f32,
                           roughness: f32) -> vec4f {
  return textureSampleLevel(table, table_sampler, matc_film_preintegrated_texcoord(NdotV, roughness),
                            0.0);
}
// A thickness per pixel (docs/thin-film.md "A thickness per pixel"): <name>.film.<ext> stacks the
// tables of `slices` films uniform over the material's thickness range, 65 x 18 slices texels:
// rows 0 to slices - 1 F, then for each roughness node j the slices rows of Fbar. `thickness` is
// the coordinate in [0, 1] over the range (a thickness texture's green channel, as glTF's
// iridescenceThicknessTexture); matc_film_thickness_<name> maps nanometres to it. A light is one
// fetch, over (sqrt(mu), thickness); image light two, at the roughness nodes either side, mixed.
// Where along the thickness axis a read lands, in texels: held 1/1024 of a slice inside the end
// slices, since in a texture thousands of rows tall a float texcoord on the last slice's texel
// centre can land past it, in the next block (the CPU runtime holds it so too).
fn matc_film_stack_slice(thickness: f32, slices: f32) -> f32 {
  let last = slices - 1.0;
  return clamp(clamp(thickness, 0.0, 1.0) * last, 1.0 / 1024.0, last - 1.0 / 1024.0) + 0.5;
}
fn matc_film_stack_fresnel_texcoord(mu: f32, thickness: f32, slices: f32) -> vec2f {
  let s = matc_film_stack_slice(thickness, slices);
  return vec2f(sqrt(clamp(mu, 0.0, 1.0)) * (64.0 / 65.0) + 0.5 / 65.0, s / (18.0 * slices));
}
// xy and xz: the texcoords at the roughness nodes below and above; w: the weight of the one above.
fn matc_film_stack_preintegrated_texcoords(NdotV: f32, roughness: f32, thickness: f32,
                                           slices: f32) -> vec4f {
  let x = sqrt(clamp(NdotV, 0.0, 1.0)) * (64.0 / 65.0) + 0.5 / 65.0;
  let r = sqrt(clamp((roughness - 0.05) * (1.0 / 0.95), 0.0, 1.0)) * 16.0;
  let j = min(floor(r), 15.0);
  let s = matc_film_stack_slice(thickness, slices);
  let height = 18.0 * slices;
  return vec4f(x, (slices * (1.0 + j) + s) / height, (slices * (2.0 + j) + s) / height, r - j);
}
fn matc_film_stack_fresnel(table: texture_2d<f32>, table_sampler: sampler, mu: f32,
                           thickness: f32, slices: f32) -> vec4f {
  return textureSampleLevel(table, table_sampler,
                            matc_film_stack_fresnel_texcoord(mu, thickness, slices), 0.0);
}
fn matc_film_stack_preintegrated(table: texture_2d<f32>, table_sampler: sampler, NdotV: f32,
                                 roughness: f32, thickness: f32, slices: f32) -> vec4f {
  let c = matc_film_stack_preintegrated_texcoords(NdotV, roughness, thickness, slices);
  return mix(textureSampleLevel(table, table_sampler, c.xy, 0.0),
             textureSampleLevel(table, table_sampler, c.xz, 0.0), c.w);
}
{{coefficient_table}}
{{area_lights}}
{{analytic_lut}}
{{basis_layers}}{{embedded_lut}}
