// The GLSL both WebGL integrations (three/matc-three.mjs, babylon/matc-babylon.mjs) put into their
// engine's physical shader: the declarations, the lobes' functions and the pixel's coefficients.
import { basisAliasesGlsl } from "./basis-layers.mjs";

// Declarations of the tables and the globals the patched light paths read; `uniforms` adds the
// coefficient sources' vector uniforms (engines that bind them through a uniform block declare
// those themselves).
// `build` (loadMatcBuild's): a per-material build's aliases of each basis' functions follow the
// library (basis-layers.mjs).
export function declarationsGlsl(library, { uniforms, build }) {
  const vectors = uniforms ? "\tuniform vec4 matc_red;\n\tuniform vec4 matc_green;\n\tuniform vec4 matc_blue;\n" : "";
  const colours = uniforms ? "\tuniform vec3 matc_reflectivity;\n\tuniform vec3 matc_edge_tint;\n" : "";
  return `
${library}
${basisAliasesGlsl(build)}uniform sampler2D matc_lut;
uniform sampler2D matc_ltc;
#if defined(MATC_SOURCE_TABLE)
	uniform sampler2D matc_coefficient_table;
	uniform sampler2D matc_reflectivity_map;
	uniform sampler2D matc_edge_tint_map;
${colours}#elif defined(MATC_SOURCE_F0_TABLE)
	uniform highp sampler2D matc_f0_table;
#elif defined(MATC_SOURCE_BAKED)
	uniform sampler2D matc_c2_map;
	uniform sampler2D matc_c3_map;
	#ifdef MATC_BAKED_F0
		uniform sampler2D matc_f0_map;
	#endif
#else
${vectors}#endif
MatcFresnelCoefficients matc_c;  // this pixel's coefficients
vec4 matc_bbar;                  // and its texel of matc_lut, set before the lights
#ifdef MATC_FILMED
	uniform highp sampler2D matc_film_table;  // a filmed metal's own table (docs/thin-film.md)
	vec4 matc_film_bbar;                      // its Fbar texel at the pixel's (NdotV, roughness)
#endif
`;
}

// What the patched light paths call for the base lobe, and for a coated material's coat lobe
// (docs/coating.md): the library's functions on this pixel's coefficients, for a filmed metal its
// own table's texels (matc_film_table, MATC_FILMED), or, for a material
// loaded with a coat (build.loadMaterial), its own snippet's (<name>.glsl: the metal seen through
// the coat, attenuated and tinted by it, and the coat's dielectric Fresnel with its weight).
// matc_coat_bbar is matc_lut's texel at the coat's roughness and matc_ndotv the pixel's NdotV,
// set before the lights with the rest.
export function lobesGlsl(material) {
  if (material?.film && material?.coat) {
    // A filmed metal under a coat (docs/thin-film.md, "Under a coat"): its table's texels are the
    // base lobe, the coat's transmission and tint included; the coat lobe is its snippet's, and the
    // base's multiple scattering a bare metal's with the filmed metal's F0 under the coat.
    const name = material.name;
    return `
${material.coat.snippet}
vec4 matc_coat_bbar;
float matc_ndotv;
vec3 matc_base_fresnel(float mu) { return matc_fresnel_${name}(MATC_FILM_FRESNEL(matc_film_table, mu)); }
vec3 matc_base_preintegrated() { return matc_fresnel_preintegrated_${name}(matc_film_bbar); }
vec3 matc_base_compensation() { return matc_energy_compensation(matc_under_coat_coefficients_${name}, matc_bbar); }
float matc_coat_lobe_fresnel(float mu) { return matc_coat_fresnel_${name}(mu); }
float matc_coat_transmission() { return matc_coat_transmission_${name}(matc_ndotv); }
float matc_coat_lobe_preintegrated() { return matc_coat_fresnel_preintegrated_${name}(matc_coat_bbar); }
`;
  }
  if (material?.film) {
    // A filmed metal (docs/thin-film.md): F and Fbar are its own table's texels (what its
    // snippet's matc_fresnel_<name>(film_texel) returns), fetched by the library; its 4-term
    // coefficients (matc_c) give F0 for the multiple scattering.
    return `
vec3 matc_base_fresnel(float mu) { return MATC_FILM_FRESNEL(matc_film_table, mu).rgb; }
vec3 matc_base_preintegrated() { return matc_film_bbar.rgb; }
vec3 matc_base_compensation() { return matc_energy_compensation(matc_c, matc_bbar); }
float matc_coat_transmission() { return 1.0; }  // no coat over the engine's dielectric
`;
  }
  if (!material?.coat) {
    return `
vec3 matc_base_fresnel(float mu) { return matc_source_fresnel(matc_c, mu); }
vec3 matc_base_preintegrated() { return matc_fresnel_preintegrated(matc_c, matc_bbar); }
vec3 matc_base_compensation() { return matc_energy_compensation(matc_c, matc_bbar); }
float matc_coat_transmission() { return 1.0; }  // no coat over the engine's dielectric
`;
  }
  const name = material.name;
  return `
${material.coat.snippet}
vec4 matc_coat_bbar;
float matc_ndotv;
// The base's multiple scattering is a bare metal's, with the metal's F0 under the coat.
#ifdef MATC_SOURCE_F0_TABLE
// A textured metal: the metal's coefficients under the coat per pixel (and in air, matc_c, which a
// partial coat mixes in), from its F0 table.
MatcFresnelCoefficients matc_under_coat;
vec3 matc_base_fresnel(float mu) { return matc_fresnel_textured_${name}(matc_c, matc_under_coat, mu); }
vec3 matc_base_preintegrated() {
	return matc_fresnel_preintegrated_textured_${name}(matc_c, matc_under_coat, matc_bbar, matc_coat_bbar, matc_ndotv);
}
vec3 matc_base_compensation() { return matc_energy_compensation(matc_under_coat, matc_bbar); }
#else
vec3 matc_base_fresnel(float mu) { return matc_fresnel_${name}(mu); }
vec3 matc_base_preintegrated() { return matc_fresnel_preintegrated_${name}(matc_bbar, matc_coat_bbar, matc_ndotv); }
vec3 matc_base_compensation() { return matc_energy_compensation(matc_under_coat_coefficients_${name}, matc_bbar); }
#endif
float matc_coat_lobe_fresnel(float mu) { return matc_coat_fresnel_${name}(mu); }
// glTF's metal-rough model under the coat: what the engine's dielectric reflects (diffuse too) times this.
float matc_coat_transmission() { return matc_coat_transmission_${name}(matc_ndotv); }
float matc_coat_lobe_preintegrated() { return matc_coat_fresnel_preintegrated_${name}(matc_coat_bbar); }
`;
}

// What the engine's main() computes before its lights: the pixel's coefficients (MATC_SOURCE_*
// says from where; maps at texture coordinate `uv`, F0 of baked metals without an F0 map, of
// Schlick metals and of F0-table metals from `baseColour`) and matc_lut's texel at (`ndotv`, `roughness`), and for a coated material
// (MATC_COATED) at (`ndotv`, `coatRoughness`), all GLSL expressions of the engine.
export function pixelSetupGlsl({ uv, baseColour, ndotv, roughness, coatRoughness }) {
  return `
#if defined(MATC_SOURCE_TABLE)
	{
		vec3 matc_r = texture(matc_reflectivity_map, ${uv}).rgb * matc_reflectivity;
		vec3 matc_g = texture(matc_edge_tint_map, ${uv}).rgb * matc_edge_tint;
		matc_c = MATC_COEFFICIENTS_FROM_TABLE(matc_coefficient_table, matc_r, matc_g);
	}
#elif defined(MATC_SOURCE_BAKED)
	#ifdef MATC_BAKED_F0
		vec3 matc_f0 = texture(matc_f0_map, ${uv}).rgb;
	#else
		vec3 matc_f0 = ${baseColour};
	#endif
	matc_c = matc_coefficients_from_baked(matc_f0, texture(matc_c2_map, ${uv}).rgb, texture(matc_c3_map, ${uv}).rgb);
#elif defined(MATC_SOURCE_F0_TABLE)
	// A textured metal under an edge colour or a coat: its coefficients at the engine's base colour
	// (factor times texture), interpolated between its F0 table's entries (docs/gltf.md).
	matc_c = MATC_COEFFICIENTS_FROM_F0_TABLE(matc_f0_table, ${baseColour});
	#ifdef MATC_COATED
		matc_under_coat = MATC_UNDER_COAT_FROM_F0_TABLE(matc_f0_table, ${baseColour});
	#endif
#elif defined(MATC_SOURCE_SCHLICK)
	// Schlick's curve of the engine's base colour (a glTF metal's factor times its texture), from
	// the curve's coefficients at F0 = 0.
	matc_c = matc_coefficients_from_f0(MatcFresnelCoefficients(matc_red, matc_green, matc_blue), ${baseColour});
#else
	matc_c = MatcFresnelCoefficients(matc_red, matc_green, matc_blue);
#endif
	matc_bbar = texture(matc_lut, matc_source_lut_texcoord(${ndotv}, ${roughness}));
#ifdef MATC_FILMED
	matc_film_bbar = MATC_FILM_PREINTEGRATED(matc_film_table, ${ndotv}, ${roughness});
#endif
#ifdef MATC_COATED
	matc_ndotv = ${ndotv};
	matc_coat_bbar = texture(matc_lut, matc_lut_texcoord(matc_ndotv, ${coatRoughness}));
#endif
`;
}
