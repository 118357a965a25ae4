// matc {{version}}: the Fresnel decomposition of Belcour, Bati and Barla (SIGGRAPH 2020),
// F(mu) = sum_i c_i b_i(mu). Generated (inputs {{inputs_hash}}); do not edit, rerun matc.
// HLSL shader model 5.0+ (DXC, FXC, glslang); every name starts with matc_ / Matc / MATC_.
#ifndef MATC_FRESNEL_HLSL
#define MATC_FRESNEL_HLSL

// Material snippets check this to refuse a library from another matc version.
#define MATC_VERSION {{version_number}}
// Width and height of the preintegrated table this build wrote (matc_lut.*).
#define MATC_LUT_SIZE {{lut_size}}

// A material's coefficients c_0..c_3, one row per colour channel: 48 bytes, three float4
// registers in a constant buffer.
struct MatcFresnelCoefficients {
  float4 red;
  float4 green;
  float4 blue;
};

// sum_i c_i v_i per channel; matc_combine clamps it at 0, where a truncated basis dips below it.
float3 matc_combine_sum(MatcFresnelCoefficients c, float4 v) {
  return float3(dot(c.red, v), dot(c.green, v), dot(c.blue, v));
}
float3 matc_combine(MatcFresnelCoefficients c, float4 v) {
  return max(matc_combine_sum(c, v), 0.0);
}

{{basis_function}}
{{lut_texcoord}}
// The preintegrated Fresnel from the table's texel bbar at matc_lut_texcoord(NdotV, roughness):
// sum_i c_i bbar_i, written with c_1 = 1 - c_0 (which every coefficient source sets) as
// bbar_1 + c_0 (bbar_0 - bbar_1) + c_2 bbar_2 + c_3 bbar_3, three multiply-adds a channel.
// Without the clamp at 0, for curves matc proved non-negative (docs/shaders.md).
float3 matc_fresnel_preintegrated_sum(MatcFresnelCoefficients c, float4 bbar) {
  float3 c0 = float3(c.red.x, c.green.x, c.blue.x);
  float3 c2 = float3(c.red.z, c.green.z, c.blue.z);
  float3 c3 = float3(c.red.w, c.green.w, c.blue.w);
  return bbar.y + c0 * (bbar.x - bbar.y) + c2 * bbar.z + c3 * bbar.w;
}
// Clamped at 0, where a truncated curve dips below it: what every coefficient source may use.
float3 matc_fresnel_preintegrated(MatcFresnelCoefficients c, float4 bbar) {
  return max(matc_fresnel_preintegrated_sum(c, bbar), 0.0);
}

// Turquin (2019)'s multiple-scattering scale for the specular lobe, 1 + F0 (1 - E) / E, with
// E = bbar.x the directional albedo of the GGX lobe (F = 1).
float3 matc_energy_compensation(MatcFresnelCoefficients c, float4 bbar) {
  float3 f0 = float3(c.red.x, c.green.x, c.blue.x);
  float albedo = max(bbar.x, 1e-4);  // guards the NdotV = 0 column
  return 1.0 + f0 * ((1.0 - albedo) / albedo);
}
// glTF's metal-rough model per pixel (docs/gltf.md): glTF's BRDF mixes its dielectric and metal
// BRDFs by metalness (metallicFactor times the metallic-roughness texture's blue channel); matc's
// Fresnel replaces the metal's only. `dielectric` and `metal` are the same term of each lobe (F for
// a light, each with its own multiple-scattering scale; the preintegrated F for image light).
float3 matc_metal_rough(float3 dielectric, float3 metal, float metalness) {
  return lerp(dielectric, metal, saturate(metalness));
}
// glTF's dielectric Fresnel, Schlick's curve from f0 to f90 (f0 0.04 and f90 1 at glTF's index
// 1.5; KHR_materials_ior and KHR_materials_specular change both), for an engine without its own.
float3 matc_dielectric_fresnel(float3 f0, float3 f90, float VdotH) {
  float m = clamp(1.0 - VdotH, 0.0, 1.0);
  float m2 = m * m;
  return f0 + (f90 - f0) * (m2 * m2 * m);
}

// ---- Metals under a thin film: their own table (docs/thin-film.md). ----
// A filmed metal's <name>.film.<ext>, 65 x 18 texels: row 0 F over sqrt(mu), rows 1-17 the
// preintegrated F over sqrt(NdotV) and sqrt((roughness - 0.05) / 0.95), texel centres on the
// nodes. Sample it as the preintegrated table (linear, clamp to edge) at these coordinates; its
// rgb is F (or Fbar) itself.
float2 matc_film_fresnel_texcoord(float mu) {
  return float2(sqrt(saturate(mu)) * (64.0 / 65.0) + 0.5 / 65.0, 0.5 / 18.0);
}
float2 matc_film_preintegrated_texcoord(float NdotV, float roughness) {
  float x = sqrt(saturate(NdotV));
  float y = sqrt(saturate((roughness - 0.05) * (1.0 / 0.95)));
  return float2(x * (64.0 / 65.0) + 0.5 / 65.0, y * (16.0 / 18.0) + 1.5 / 18.0);
}
// The fetches from TABLE (a Texture2D) through SAMPLER (a SamplerState).
float4 matc_film_fresnel(Texture2D<float4> table, SamplerState table_sampler, float mu) {
  return table.SampleLevel(table_sampler, matc_film_fresnel_texcoord(mu), 0.0);
}
float4 matc_film_preintegrated(Texture2D<float4> table, SamplerState table_sampler, float NdotV,
                               float roughness) {
  return table.SampleLevel(table_sampler, matc_film_preintegrated_texcoord(NdotV, roughness), 0.0);
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
float matc_film_stack_slice(float thickness, float slices) {
  float last = slices - 1.0;
  return clamp(saturate(thickness) * last, 1.0 / 1024.0, last - 1.0 / 1024.0) + 0.5;
}
float2 matc_film_stack_fresnel_texcoord(float mu, float thickness, float slices) {
  float s = matc_film_stack_slice(thickness, slices);
  return float2(sqrt(saturate(mu)) * (64.0 / 65.0) + 0.5 / 65.0, s / (18.0 * slices));
}
// xy and xz: the texcoords at the roughness nodes below and above; w: the weight of the one above.
float4 matc_film_stack_preintegrated_texcoords(float NdotV, float roughness, float thickness,
                                               float slices) {
  float x = sqrt(saturate(NdotV)) * (64.0 / 65.0) + 0.5 / 65.0;
  float r = sqrt(saturate((roughness - 0.05) * (1.0 / 0.95))) * 16.0;
  float j = min(floor(r), 15.0);
  float s = matc_film_stack_slice(thickness, slices);
  float height = 18.0 * slices;
  return float4(x, (slices * (1.0 + j) + s) / height, (slices * (2.0 + j) + s) / height, r - j);
}
float4 matc_film_stack_fresnel(Texture2D<float4> table, SamplerState table_sampler, float mu,
                               float thickness, float slices) {
  return table.SampleLevel(table_sampler, matc_film_stack_fresnel_texcoord(mu, thickness, slices),
                           0.0);
}
float4 matc_film_stack_preintegrated(Texture2D<float4> table, SamplerState table_sampler,
                                     float NdotV, float roughness, float thickness, float slices) {
  float4 c = matc_film_stack_preintegrated_texcoords(NdotV, roughness, thickness, slices);
  return lerp(table.SampleLevel(table_sampler, c.xy, 0.0),
              table.SampleLevel(table_sampler, c.xz, 0.0), c.w);
}
{{coefficient_table}}
{{area_lights}}
{{analytic_lut}}
{{basis_layers}}{{embedded_lut}}
#endif  // MATC_FRESNEL_HLSL
