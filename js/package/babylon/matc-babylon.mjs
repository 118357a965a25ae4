// matc's Fresnel inside Babylon.js's PBRMaterial, as a material plugin: the material becomes a
// matc metal in every light path Babylon has (point, spot, directional and hemispheric lights,
// image lighting with its energy conservation, rect area lights), with the rest of the engine
// untouched; a coated matc material's coat lobe replaces Babylon's clear coat. The plugin replaces Babylon's own shader text at anchors checked when it is created:
// a Babylon whose shaders changed makes it throw, never render wrongly. docs/web-engines.md says
// what each replacement does.
//
//   import { loadMatcBuild, useMatcFresnel } from "matc/babylon";
//   const build = await loadMatcBuild("matc-out/", scene);  // a `matc -o matc-out` build directory
//   const gold = useMatcFresnel(new PBRMaterial("gold", scene), build,
//                               { material: await build.loadMaterial("gold") });
import { Constants } from "@babylonjs/core/Engines/constants.js";
import { MaterialPluginBase } from "@babylonjs/core/Materials/materialPluginBase.js";
import { RawTexture } from "@babylonjs/core/Materials/Textures/rawTexture.js";
import { Texture } from "@babylonjs/core/Materials/Textures/texture.js";
import { ShaderStore } from "@babylonjs/core/Engines/shaderStore.js";
import { Vector3, Vector4 } from "@babylonjs/core/Maths/math.vector.js";
import { AbstractEngine } from "@babylonjs/core/Engines/abstractEngine.js";
import "@babylonjs/core/Shaders/pbr.fragment.js";  // registers the shader text the anchors are checked against
import { MatcWebError, anchorPattern, checkAnchors, checkAreaLights, checkIridescence, checkLayeredAreaLights, declarationsGlsl,
         f0TableTexels, kF0TableEntries, matcBuildFiles, lobesGlsl, pixelSetupGlsl, rgbOf, sourceKind,
         basisDefine, buildBases, sourceBasis }
  from "../matc-build.mjs";

export { MatcWebError };

// The @babylonjs/core versions whose shaders the replacements were written against and tested
// with (tests/js/check-babylon-engine.mjs).
export const kTestedBabylonVersions = ["9.31.0"];

// This pixel's coefficients and its texel of matc_lut at (NdotV, roughness) as Babylon shades them.
const kPixelSetup = `${pixelSetupGlsl({ uv: "vMainUV1", baseColour: "surfaceAlbedo.rgb", roughness: "roughness",
                                        ndotv: "absEps(dot(normalW, viewDirectionW))", coatRoughness: "vClearCoatParams.y" })}
#ifdef MATC_METAL_ROUGH
	matc_dielectric_transmission = matc_coat_transmission();
	matc_dielectric_energy = vec3(matc_dielectric_transmission);
	matc_metal_energy = vec3(1.0);
#endif
`;

// Declarations: the matc library, the tables, the globals the patched light paths read (the
// vector uniforms come through the plugin's uniform block), the lobes' functions (a coated
// material's from its snippet), the rect-area-light terms and a coated material's coat lobe.
const kDeclarations = (library, material, build) => `
#ifdef MATC_FRESNEL
${declarationsGlsl(library, { uniforms: false, build })}
${lobesGlsl(material)}
#ifdef MATC_METAL_ROUGH
// glTF's metal-rough model per pixel (docs/gltf.md): Babylon's own dielectric lobe mixed with
// matc's metal by metallic, each with its own energy conservation (Babylon scales the sum by one
// factor of its blended F0; matc_metal_rough takes each lobe with its own, set before the lights).
// The dielectric's F90, which Babylon blends with the metal's, from its reflectivity block. Under a
// matc coat, the coat's transmission at NdotV scales all the dielectric reflects (glTF's layering
// of a clear coat; docs/gltf.md): its specular through matc_dielectric_energy, its diffuse albedo.
vec3 matc_dielectric_f90;
float matc_dielectric_transmission;
vec3 matc_dielectric_energy;
vec3 matc_metal_energy;
#endif
// A rect area light of Babylon's (centre, half width, half height; one-sided like Babylon's):
// its corners, or false where P is behind it.
bool matc_rect_corners(vec3 P, vec3 centre, vec3 halfWidth, vec3 halfHeight, out vec3 q0, out vec3 q1, out vec3 q2, out vec3 q3) {
	q0 = centre + halfWidth - halfHeight;
	q1 = centre - halfWidth - halfHeight;
	q2 = centre - halfWidth + halfHeight;
	q3 = centre + halfWidth + halfHeight;
	return dot(cross(q1 - q0, q3 - q0), P - q0) >= 0.0;
}
// Its radiance on the base lobe: matc's LTC times sum_i c_i bbar_i, as matc_ltc_quad_light
// (areaLights "quality": as matc_ltc_quad_light_following).
vec3 matc_rect_area_light(vec3 N, vec3 V, vec3 P, float roughness, vec3 centre, vec3 halfWidth, vec3 halfHeight) {
	vec3 q0, q1, q2, q3;
	if (!matc_rect_corners(P, centre, halfWidth, halfHeight, q0, q1, q2, q3)) return vec3(0.0);
	vec4 ltc = texture2D(matc_ltc, matc_ltc_texcoord(absEps(dot(N, V)), roughness));
#ifdef MATC_QUALITY_LTC
	return matc_source_ltc_quad_light_following(matc_c, matc_bbar, ltc, roughness, N, V, P, q0, q1, q2, q3);
#else
	return matc_ltc_quad_integral(matc_ltc_transform(N, V, ltc), P, q0, q1, q2, q3) * matc_base_preintegrated();
#endif
}
#ifdef MATC_COATED
// ... and on a coated material's coat lobe, matc's LTC at the coat's roughness (Babylon's rect
// lights have no coat lobe of their own).
vec3 matc_rect_coat_light(vec3 N, vec3 V, vec3 P, float coatRoughness, vec3 centre, vec3 halfWidth, vec3 halfHeight) {
	vec3 q0, q1, q2, q3;
	if (!matc_rect_corners(P, centre, halfWidth, halfHeight, q0, q1, q2, q3)) return vec3(0.0);
	vec4 ltc = texture2D(matc_ltc, matc_ltc_texcoord(absEps(dot(N, V)), coatRoughness));
	return vec3(matc_ltc_quad_integral(matc_ltc_transform(N, V, ltc), P, q0, q1, q2, q3) * matc_coat_lobe_preintegrated());
}
// The coat lobe of a direct light as Babylon's computeClearCoatLighting computes it (GGX D,
// Kelemen's visibility) with the coat's fitted Fresnel and weight; w = 1: the base lobe carries
// the coat's attenuation already.
vec4 matc_coat_light(preLightingInfo info, vec3 Ncc, float geometricRoughnessFactor, vec3 lightColor) {
	float NccdotL = saturateEps(dot(Ncc, info.L));
	float NccdotH = saturateEps(dot(Ncc, info.H));
	float alphaG = convertRoughnessToAverageSlope(max(info.roughness, geometricRoughnessFactor));
	float term = matc_coat_lobe_fresnel(info.VdotH) * normalDistributionFunction_TrowbridgeReitzGGX(NccdotH, alphaG) *
	             visibility_Kelemen(info.VdotH);
	return vec4(term * info.attenuation * NccdotL * lightColor, 1.0);
}
#endif
#endif
`;

// Image lighting with metalRough (under Babylon's own conductor model and its OpenPBR one alike):
// each lobe's energy conservation, then Babylon's dielectric lookup mixed with matc's metal by
// metallic; opens the #else of what stands without metalRough.
const kMetalRoughImageLighting = "\n#ifdef MATC_METAL_ROUGH\n" +
  "#ifdef MS_BRDF_ENERGY_CONSERVATION\n" +
  "matc_dielectric_energy=getEnergyConservationFactor(reflectivityOut.dielectricColorF0,environmentBrdf)*matc_dielectric_transmission;\n" +
  "matc_metal_energy=matc_base_compensation();\n" +
  "#endif\n" +
  "vec3 colorSpecularEnvironmentReflectance=matc_metal_rough(getReflectanceFromBRDFLookup(reflectivityOut.dielectricColorF0," +
  "matc_dielectric_f90,environmentBrdf)*matc_dielectric_energy,matc_base_preintegrated()*matc_metal_energy,reflectivityOut.metallic);\n" +
  "#else\n";

// Each replacement: the shader source it is checked in (Babylon's ShaderStore name), its anchor
// there (also what the plugin hands Babylon as a regular expression, applied to the shader after
// its includes are expanded, where lightFragment's {X} is a light's number), and its text.
const kPatches = [
  {
    source: "pbrPixelShader",
    anchor: "float roughness=reflectivityOut.roughness;",
    replacement: `float roughness=reflectivityOut.roughness;\n#ifdef MATC_FRESNEL\n${kPixelSetup}\n#endif\n`,
    what: "this pixel's coefficients (uniform, coefficient table or baked) and its texel of matc_lut",
  },
  {
    source: "pbrPixelShader",
    anchor: "surfaceAlbedo=reflectivityOut.surfaceAlbedo;",
    replacement: "surfaceAlbedo=reflectivityOut.surfaceAlbedo;\n#ifdef MATC_METAL_ROUGH\n" +
                 "surfaceAlbedo*=matc_dielectric_transmission;\n#endif\n",
    what: "with metalRough, the dielectric's diffuse albedo times a matc coat's transmission at NdotV (1 without one) " +
          "(glTF's layering of a clear coat; its specular through its energy factor)",
  },
  {
    source: "lightFragment",
    anchor: "coloredFresnel=fresnelSchlickGGX(preInfo.VdotH,clearcoatOut.specularEnvironmentR0,reflectivityOut.colorReflectanceF90);",
    replacement: "\n#ifdef MATC_METAL_ROUGH\n" +
                 "coloredFresnel=matc_metal_rough(fresnelSchlickGGX(preInfo.VdotH,reflectivityOut.dielectricColorF0,matc_dielectric_f90)*" +
                 "matc_dielectric_energy,matc_base_fresnel(preInfo.VdotH)*matc_metal_energy,reflectivityOut.metallic);\n" +
                 "#else\ncoloredFresnel=matc_base_fresnel(preInfo.VdotH);\n#endif\n",
    what: "punctual lights: fresnelSchlickGGX(VdotH, R0, R90) becomes matc_fresnel(c, VdotH) (a coated " +
          "material's base lobe: the metal through the coat)",
  },
  {
    source: "lightFragment",
    anchor: "{vec3 metalFresnel=reflectivityOut.specularWeight*getF82Specular(preInfo.VdotH,clearcoatOut.specularEnvironmentR0,reflectivityOut.colorReflectanceF90,reflectivityOut.roughness);" +
            "vec3 dielectricFresnel=fresnelSchlickGGX(preInfo.VdotH,reflectivityOut.dielectricColorF0,reflectivityOut.colorReflectanceF90);" +
            "coloredFresnel=mix(dielectricFresnel,metalFresnel,reflectivityOut.metallic);}",
    replacement: "\n#ifdef MATC_METAL_ROUGH\n" +
                 "coloredFresnel=matc_metal_rough(fresnelSchlickGGX(preInfo.VdotH,reflectivityOut.dielectricColorF0,matc_dielectric_f90)*" +
                 "matc_dielectric_energy,matc_base_fresnel(preInfo.VdotH)*matc_metal_energy,reflectivityOut.metallic);\n" +
                 "#else\n" +
                 "{vec3 metalFresnel=matc_base_fresnel(preInfo.VdotH);" +
                 "vec3 dielectricFresnel=fresnelSchlickGGX(preInfo.VdotH,reflectivityOut.dielectricColorF0,reflectivityOut.colorReflectanceF90);" +
                 "coloredFresnel=mix(dielectricFresnel,metalFresnel,reflectivityOut.metallic);}\n" +
                 "#endif\n",
    what: "punctual lights under Babylon's OpenPBR conductor model (a glTF metal with an edge colour): the " +
          "F82 metal Fresnel, times the specular weight, becomes matc_fresnel(c, VdotH) (the edge colour and its " +
          "weight are in the coefficients); with metalRough, mixed with Babylon's dielectric as above",
  },
  {
    source: "lightFragment",
    anchor: "info.clearCoat=computeClearCoatLighting(preInfo,clearcoatOut.clearCoatNormalW,clearcoatOut.clearCoatAARoughnessFactors.x,clearcoatOut.clearCoatIntensity,diffuse{X}.rgb);",
    replacement: "\n#ifdef MATC_COATED\n" +
                 "info.clearCoat=matc_coat_light(preInfo,clearcoatOut.clearCoatNormalW,clearcoatOut.clearCoatAARoughnessFactors.x,diffuse$1.rgb);\n" +
                 "#else\n" +
                 "info.clearCoat=computeClearCoatLighting(preInfo,clearcoatOut.clearCoatNormalW,clearcoatOut.clearCoatAARoughnessFactors.x,clearcoatOut.clearCoatIntensity,diffuse$1.rgb);\n" +
                 "#endif\n",
    what: "a coated material's coat lobe, punctual lights: Babylon's Schlick coat Fresnel becomes the coat's " +
          "fitted dielectric Fresnel times its weight, and the base is no longer scaled by 1 - F (matc's base lobe " +
          "carries the coat's attenuation and tint)",
  },
  {
    source: "lightFragment",
    anchor: "info.specular=computeAreaSpecularLighting(preInfo,light{X}.vLightSpecular.rgb,clearcoatOut.specularEnvironmentR0,reflectivityOut.colorReflectanceF90);",
    replacement: "\n#ifdef MATC_ENGINE_LTC\n" +
                 "info.specular=light$1.vLightSpecular.rgb*matc_base_preintegrated()*preInfo.areaLightSpecular;\n" +
                 "#else\n" +
                 "info.specular=light$1.vLightSpecular.rgb*matc_rect_area_light(normalW,viewDirectionW,vPositionW,roughness," +
                 "light$1.vLightData.xyz,light$1.vLightWidth.xyz,light$1.vLightHeight.xyz);\n#endif\n" +
                 "#ifdef MATC_METAL_ROUGH\n" +
                 "info.specular=matc_metal_rough(computeAreaSpecularLighting(preInfo,light$1.vLightSpecular.rgb,reflectivityOut.dielectricColorF0," +
                 "matc_dielectric_f90)*matc_dielectric_energy,info.specular*matc_metal_energy,reflectivityOut.metallic);\n" +
                 "#endif\n" +
                 "#ifdef MATC_COATED\n" +
                 "info.clearCoat=vec4(light$1.vLightSpecular.rgb*matc_rect_coat_light(normalW,viewDirectionW,vPositionW," +
                 "clearcoatOut.clearCoatRoughness,light$1.vLightData.xyz,light$1.vLightWidth.xyz,light$1.vLightHeight.xyz),1.0);\n" +
                 "#endif\n",
    what: "rect area lights: Babylon's LTC and its two-channel Fresnel become matc's LTC times sum_i c_i bbar_i " +
          "(with areaLights: \"engine\", Babylon's LTC shape times sum_i c_i bbar_i); a coated material's coat " +
          "lobe, which Babylon's rect lights lack, is added with matc's LTC at the coat's roughness",
  },
  {
    source: "pbrBlockReflectance",
    anchor: "vec3 colorSpecularEnvironmentReflectance=getReflectanceFromBRDFLookup(clearcoatOut.specularEnvironmentR0,reflectivityOut.colorReflectanceF90,environmentBrdf);",
    replacement: kMetalRoughImageLighting + "vec3 colorSpecularEnvironmentReflectance=matc_base_preintegrated();\n#endif\n",
    what: "image lighting: the BRDF lookup's R0/R90 mix becomes sum_i c_i bbar_i (with metalRough, mixed by " +
          "metallic with Babylon's own dielectric lookup, each lobe with its energy conservation)",
  },
  {
    source: "pbrBlockReflectance",
    anchor: "vec3 metalEnvironmentReflectance=reflectivityOut.specularWeight*getF82Specular(NdotV,clearcoatOut.specularEnvironmentR0,reflectivityOut.colorReflectanceF90,reflectivityOut.roughness);" +
            "vec3 dielectricEnvironmentReflectance=getReflectanceFromBRDFLookup(reflectivityOut.dielectricColorF0,reflectivityOut.colorReflectanceF90,environmentBrdf);" +
            "vec3 colorSpecularEnvironmentReflectance=mix(dielectricEnvironmentReflectance,metalEnvironmentReflectance,reflectivityOut.metallic);",
    replacement: kMetalRoughImageLighting +
                 "vec3 metalEnvironmentReflectance=matc_base_preintegrated();" +
                 "vec3 dielectricEnvironmentReflectance=getReflectanceFromBRDFLookup(reflectivityOut.dielectricColorF0,reflectivityOut.colorReflectanceF90,environmentBrdf);" +
                 "vec3 colorSpecularEnvironmentReflectance=mix(dielectricEnvironmentReflectance,metalEnvironmentReflectance,reflectivityOut.metallic);\n" +
                 "#endif\n",
    what: "image lighting under Babylon's OpenPBR conductor model (a glTF metal with an edge colour): the F82 " +
          "metal term becomes sum_i c_i bbar_i; with metalRough, mixed with Babylon's dielectric lookup as above",
  },
  {
    source: "pbrBlockFinalLitComponents",
    anchor: "vec3 coloredEnergyConservationFactor=getEnergyConservationFactor(clearcoatOut.specularEnvironmentR0,environmentBrdf);",
    replacement: "\n#ifdef MATC_METAL_ROUGH\nvec3 coloredEnergyConservationFactor=vec3(1.0);\n#else\n" +
                 "vec3 coloredEnergyConservationFactor=matc_base_compensation();\n#endif\n",
    what: "energy conservation of the specular lobe (direct and image lighting): F0 and E from matc (a coated " +
          "material's: the metal's F0 under the coat; with metalRough, 1: each lobe carries its own)",
  },
  {
    source: "pbrBlockReflectivity",
    anchor: "outParams.colorReflectanceF90=mix(dielectricColorF90,conductorColorF90,outParams.metallic);",
    replacement: "\n#ifdef MATC_METAL_ROUGH\nmatc_dielectric_f90=dielectricColorF90;\n#endif\n" +
                 "outParams.colorReflectanceF90=mix(dielectricColorF90,conductorColorF90,outParams.metallic);\n",
    what: "with metalRough, the dielectric's F90 kept for its own lobe (Babylon blends it with the metal's)",
  },
  {
    source: "pbrBlockClearcoat",
    anchor: "vec3 clearCoatEnvironmentReflectance=getReflectanceFromBRDFLookup(vec3(vClearCoatRefractionParams.x),environmentClearCoatBrdf);",
    replacement: "\n#ifdef MATC_COATED\nvec3 clearCoatEnvironmentReflectance=vec3(matc_coat_lobe_preintegrated());\n#else\n" +
                 "vec3 clearCoatEnvironmentReflectance=getReflectanceFromBRDFLookup(vec3(vClearCoatRefractionParams.x),environmentClearCoatBrdf);\n" +
                 "#endif\n",
    what: "a coated material's coat lobe, image lighting: the BRDF lookup's Schlick coat becomes the coat's " +
          "preintegrated Fresnel (matc_lut at the coat's roughness) times its weight",
  },
  {
    source: "pbrBlockClearcoat",
    anchor: "outParams.conservationFactor=(1.-fresnelIBLClearCoat);",
    replacement: "\n#ifdef MATC_COATED\noutParams.conservationFactor=1.0;\n#else\noutParams.conservationFactor=(1.-fresnelIBLClearCoat);\n#endif\n",
    what: "a coated material's image lighting: the base is no longer scaled by 1 - F(NdotV) (matc's base lobe " +
          "carries the coat's attenuation)",
  },
  {
    source: "pbrBlockClearcoat",
    anchor: "outParams.energyConservationFactorClearCoat=getEnergyConservationFactor(outParams.specularEnvironmentR0,environmentClearCoatBrdf);",
    replacement: "\n#ifdef MATC_COATED\noutParams.energyConservationFactorClearCoat=vec3(1.0);\n#else\n" +
                 "outParams.energyConservationFactorClearCoat=getEnergyConservationFactor(outParams.specularEnvironmentR0,environmentClearCoatBrdf);\n" +
                 "#endif\n",
    what: "a coated material's coat lobe, direct lights: no multiple-scattering factor from the base's F0 " +
          "(the coat is a dielectric whose single scattering matc preintegrates)",
  },
];

// The regular expression Babylon applies for an anchor: the anchor as checked, with
// lightFragment's {X} matching the light's number (the replacement's $1).
function shaderRegex(anchor) {
  return anchorPattern(anchor).source.replace("\\{X\\}", "(\\d+)");
}

function shaderSources() {
  return { pbrPixelShader: ShaderStore.ShadersStore.pbrPixelShader,
           ...Object.fromEntries(["lightFragment", "pbrBlockReflectance", "pbrBlockFinalLitComponents", "pbrBlockClearcoat",
                                  "pbrBlockReflectivity"]
             .map((name) => [name, ShaderStore.IncludesShadersStore[name]])) };
}

// ---- A matc build directory as Babylon.js textures. ----

// A clamped float texture of `data` without mips, sampled by `sampling`, its texels read as they are.
function floatTexture(data, width, height, format, type, sampling, scene) {
  const texture = new RawTexture(data, width, height, format, scene, false, false, sampling, type);
  texture.wrapU = texture.wrapV = Texture.CLAMP_ADDRESSMODE;
  texture.gammaSpace = false;
  return texture;
}

function tableTexture(table, scene) {
  return floatTexture(table.data, table.size, table.height,
                      table.channels === 4 ? Constants.TEXTUREFORMAT_RGBA : Constants.TEXTUREFORMAT_RG,
                      table.half ? Constants.TEXTURETYPE_HALF_FLOAT : Constants.TEXTURETYPE_FLOAT,
                      Texture.BILINEAR_SAMPLINGMODE, scene);
}

// Reads a matc build directory (`matc -o DIR`, with glsl, json and lut among --emit; ltc for rect
// area lights, coefficient-table for textured metals) into textures of `scene`.
// `source`: a build directory's URL (`matc -o DIR`), or the files of materials compiled in the page
// (compiledMatcBuildFiles(matc) of ../matc-build.mjs).
export async function loadMatcBuild(source, scene) {
  const files = await matcBuildFiles(source, "glsl");
  return { ...files, lut: tableTexture(files.lut, scene), ltc: files.ltc && tableTexture(files.ltc, scene),
           coefficientTable: files.coefficientTable && tableTexture(files.coefficientTable, scene) };
}

// ---- The plugin. ----

// A textured metal's F0 table (f0TableTexels of matc-build.mjs) as the unfiltered RGBA32F texture
// MATC_COEFFICIENTS_FROM_F0_TABLE reads with texelFetch (the interpolation is the shader's).
function f0TableTexture(table, scene) {
  return floatTexture(f0TableTexels(table), kF0TableEntries, 6, Constants.TEXTUREFORMAT_RGBA,
                      Constants.TEXTURETYPE_FLOAT, Texture.NEAREST_SAMPLINGMODE, scene);
}

// Checks a build and a source of coefficients against Babylon's shaders; what the plugin keeps.
function preparePlugin(material, build, source, areaLights, metalRough) {
  checkAreaLights(areaLights);
  if (!build || typeof build.library !== "string" || !build.lut) {
    throw new MatcWebError("useMatcFresnel needs the result of loadMatcBuild");
  }
  const version = AbstractEngine.Version;
  const tested = `@babylonjs/core ${kTestedBabylonVersions.join(", ")}`;
  if (!kTestedBabylonVersions.includes(version)) {
    console.warn(`matc: @babylonjs/core ${version} is untested (tested: ${tested}); its shaders still match the replacements`);
  }
  checkAnchors(`@babylonjs/core ${version}`, shaderSources(), kPatches, tested);
  const kind = sourceKind(build, source);
  const coat = source.material?.coat;
  const film = source.material?.film ?? null;
  // Babylon's rect lights have no coat lobe of their own: matc's LTC draws it.
  checkLayeredAreaLights(source.material, areaLights, ["matc"]);
  const colour = (value) => new Vector3(...rgbOf(value));
  const rows = kind === "material" ? source.material.coefficients : kind === "schlick" ? source.schlick.zeroF0Coefficients : null;
  const f0Table = kind === "f0Table" ? f0TableTexture(source.f0Table, material.getScene()) : null;
  // A per-material build: the define of the source's basis (null for the first; basis-layers.mjs).
  const basisDefineName = basisDefine(build, sourceBasis(build, source));
  return { build, source, kind, areaLights, metalRough, f0Table, coat, film, basisDefineName,
           filmTable: film && filmTexture(film.table, material.getScene()),
           coatId: coat ? coatIdOf(coat.snippet) : 0, reflectivity: colour(source.reflectivity), edgeTint: colour(source.edgeTint),
           coefficients: rows && rows.map((row) => new Vector4(...row)) };
}

// Babylon keys its compiled effects on the defines: each coated material's snippet (its constants)
// gets a number of its own; by text, not name, so that a material recompiled under the same name
// with another coat gets a new effect.
const kCoatIds = new Map();
function coatIdOf(snippet) {
  if (!kCoatIds.has(snippet)) kCoatIds.set(snippet, kCoatIds.size + 1);
  return kCoatIds.get(snippet);
}

// A filmed metal's table (build.loadMaterial's film.table) as a texture of `scene`, made once per
// table and scene: every material drawing the metal shares it.
const kFilmTextures = new WeakMap();
function filmTexture(table, scene) {
  const byScene = kFilmTextures.get(table) ?? new Map();
  kFilmTextures.set(table, byScene);
  if (!byScene.has(scene)) byScene.set(scene, tableTexture(table, scene));
  return byScene.get(scene);
}

// Babylon's base class asks for the shader code while it constructs the plugin, before the
// subclass can store anything: the prepared state waits here meanwhile.
let pendingPlugin = null;

export class MatcFresnelPlugin extends MaterialPluginBase {
  // source: { material } (build.loadMaterial), { schlick: { basis, zeroF0Coefficients } }
  // (Schlick's curve of the albedo, its colour times its texture: a textured glTF metal),
  // { material, f0Table } (the same under an edge colour or a coat, from its F0 table),
  // { reflectivityMap, edgeTintMap, reflectivity?, edgeTint? } (through the coefficient table) or
  // { baked: { c2Map, c3Map, f0Map? } }.
  constructor(material, build, source, areaLights = "matc", metalRough = false) {
    pendingPlugin = preparePlugin(material, build, source, areaLights, metalRough);
    try {
      super(material, "MatcFresnel", 200,
            { MATC_FRESNEL: false, MATC_SOURCE_UNIFORM: false, MATC_SOURCE_SCHLICK: false,
              MATC_SOURCE_F0_TABLE: false, MATC_SOURCE_TABLE: false,
              MATC_SOURCE_BAKED: false, MATC_BAKED_F0: false, MATC_ENGINE_LTC: false,
              MATC_QUALITY_LTC: false, MATC_COATED: false, MATC_FILMED: false, MATC_COAT_ID: 0, MATC_METAL_ROUGH: false,
              ...Object.fromEntries(buildBases(build).slice(1).map((basis) => [basisDefine(build, basis), false])) });
      Object.assign(this, pendingPlugin);
    } finally {
      pendingPlugin = null;
    }
    this._enable(true);
  }

  getClassName() {
    return "MatcFresnelPlugin";
  }

  isCompatible(shaderLanguage) {
    return shaderLanguage === 0;  // GLSL (WebGL2)
  }

  prepareDefinesBeforeAttributes(defines) {
    defines.MATC_FRESNEL = true;
    defines.MATC_SOURCE_UNIFORM = this.kind === "material";
    defines.MATC_SOURCE_SCHLICK = this.kind === "schlick";
    defines.MATC_SOURCE_F0_TABLE = this.kind === "f0Table";
    defines.MATC_SOURCE_TABLE = this.kind === "table";
    defines.MATC_SOURCE_BAKED = this.kind === "baked";
    defines.MATC_BAKED_F0 = this.kind === "baked" && Boolean(this.source.baked.f0Map);
    defines.MATC_ENGINE_LTC = this.areaLights === "engine";
    defines.MATC_QUALITY_LTC = this.areaLights === "quality";
    defines.MATC_COATED = Boolean(this.coat);
    defines.MATC_FILMED = Boolean(this.film);
    defines.MATC_COAT_ID = this.coatId;
    defines.MATC_METAL_ROUGH = Boolean(this.metalRough);
    for (const basis of buildBases(this.build).slice(1)) {
      const name = basisDefine(this.build, basis);
      defines[name] = name === this.basisDefineName;
    }
    if (this.kind === "table" || this.kind === "baked") {
      defines._needUVs = true;
      defines.MAINUV1 = true;
    }
  }

  getUniforms() {
    return {
      ubo: [{ name: "matc_red", size: 4, type: "vec4" }, { name: "matc_green", size: 4, type: "vec4" },
            { name: "matc_blue", size: 4, type: "vec4" }, { name: "matc_reflectivity", size: 3, type: "vec3" },
            { name: "matc_edge_tint", size: 3, type: "vec3" }],
      fragment: "#ifdef MATC_FRESNEL\nuniform vec4 matc_red;\nuniform vec4 matc_green;\nuniform vec4 matc_blue;\n" +
                "uniform vec3 matc_reflectivity;\nuniform vec3 matc_edge_tint;\n#endif\n",
    };
  }

  getSamplers(samplers) {
    samplers.push("matc_lut", "matc_ltc", "matc_coefficient_table", "matc_reflectivity_map", "matc_edge_tint_map",
                  "matc_c2_map", "matc_c3_map", "matc_f0_map", "matc_f0_table", "matc_film_table");
  }

  isReadyForSubMesh() {
    const textures = [this.build.lut, this.build.ltc, this.filmTable, ...this._sourceTextures()].filter(Boolean);
    return textures.every((texture) => texture.isReady());
  }

  _sourceTextures() {
    if (this.kind === "table") return [this.build.coefficientTable, this.source.reflectivityMap, this.source.edgeTintMap];
    if (this.kind === "baked") return [this.source.baked.c2Map, this.source.baked.c3Map, this.source.baked.f0Map];
    return [this.f0Table];
  }

  bindForSubMesh(uniformBuffer) {
    if (this.coefficients) {
      uniformBuffer.updateVector4("matc_red", this.coefficients[0]);
      uniformBuffer.updateVector4("matc_green", this.coefficients[1]);
      uniformBuffer.updateVector4("matc_blue", this.coefficients[2]);
    }
    uniformBuffer.updateVector3("matc_reflectivity", this.reflectivity);
    uniformBuffer.updateVector3("matc_edge_tint", this.edgeTint);
    uniformBuffer.setTexture("matc_lut", this.build.lut);
    uniformBuffer.setTexture("matc_ltc", this.build.ltc ?? this.build.lut);
    if (this.filmTable) uniformBuffer.setTexture("matc_film_table", this.filmTable);
    if (this.kind === "table") {
      uniformBuffer.setTexture("matc_coefficient_table", this.build.coefficientTable);
      uniformBuffer.setTexture("matc_reflectivity_map", this.source.reflectivityMap);
      uniformBuffer.setTexture("matc_edge_tint_map", this.source.edgeTintMap);
    } else if (this.kind === "baked") {
      uniformBuffer.setTexture("matc_c2_map", this.source.baked.c2Map);
      uniformBuffer.setTexture("matc_c3_map", this.source.baked.c3Map);
      if (this.source.baked.f0Map) uniformBuffer.setTexture("matc_f0_map", this.source.baked.f0Map);
    } else if (this.kind === "f0Table") {
      uniformBuffer.setTexture("matc_f0_table", this.f0Table);
    }
  }

  getCustomCode(shaderType) {
    if (shaderType !== "fragment") return null;
    const { build, source } = this.build ? this : pendingPlugin;
    const code = { CUSTOM_FRAGMENT_DEFINITIONS: kDeclarations(build.library, source.material, build) };
    for (const patch of kPatches) code[`!${shaderRegex(patch.anchor)}`] = patch.replacement;
    return code;
  }
}

// Makes `material` (a PBRMaterial) a matc metal: metallic 1, its Fresnel in every light path from
// `source`. Returns the material; its plugin is material.matcFresnel. options.areaLights: "matc"
// (default: matc's LTC table and horizon-clipped integral), "quality" (the same with matc's
// quality level: the lobe's shape and the Fresnel follow the light across the lobe, docs/ltc.md)
// or "engine" (Babylon's LTC shape with matc's Fresnel: cheaper; needs Babylon's LTC tables).
// options.metalRough: glTF's metal-rough model per pixel (docs/gltf.md): the material keeps its
// metallic and metallicTexture, and matc's metal replaces Babylon's metal lobe only, mixed with
// Babylon's own dielectric by the pixel's metallic in every light path (under a matc coat, the
// dielectric seen through it as glTF layers a clear coat; under Babylon's OpenPBR conductor model
// too, whose own mix of its dielectric and metal terms becomes matc_metal_rough's).
// options.bareFilm: `source` is the bare metal that matc compiled from the material's film (index 1,
// 0 nm or no coverage: docs/thin-film.md); it takes the place of Babylon's iridescence, which is
// switched off, as a filmed metal does (the glTF loaders set it).
export function useMatcFresnel(material, build, source, { areaLights = "matc", metalRough = false, bareFilm = false } = {}) {
  if (!material?.getClassName || !["PBRMaterial"].includes(material.getClassName())) {
    throw new MatcWebError("useMatcFresnel takes a Babylon.js PBRMaterial");
  }
  const replacesIridescence =
    checkIridescence(Boolean(material.iridescence?.isEnabled), source?.material?.film, bareFilm);
  material.matcFresnel = new MatcFresnelPlugin(material, build, source, areaLights, metalRough);
  // matc's film (or the bare metal a film of index 1 is) in place of Babylon's iridescence.
  if (replacesIridescence) material.iridescence.isEnabled = false;
  const coat = material.matcFresnel.coat;
  if (coat) {
    // The coat's lobe and layering are the compiled material's (weight, index, colour, roughness):
    // Babylon's clear coat only switches its coat light paths on.
    Object.assign(material.clearCoat, { isEnabled: true, intensity: 1, roughness: coat.roughness,
                                        indexOfRefraction: coat.ior, isTintEnabled: false });
  }
  if (!metalRough) {
    material.metallic = 1;
    material.metallicTexture = null;
  }
  return material;
}
