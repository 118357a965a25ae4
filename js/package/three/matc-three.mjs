// matc's Fresnel inside three.js's own physical material: a MeshStandardMaterial or
// MeshPhysicalMaterial becomes a matc metal in every light path the engine has (punctual lights,
// image lighting with its multiple scattering, rect area lights), with the rest of the engine
// (shadows, fog, tone mapping, maps, clearcoat over a bare metal) untouched; a coated matc
// material's coat lobe replaces three's clearcoat. Patched at run time from the engine's
// own shader chunks; a chunk that changed makes it throw, never render wrongly. README.md says
// how to use it and docs/web-engines.md what each patch replaces.
//
//   import { loadMatcBuild, useMatcFresnel } from "matc/three";
//   const build = await loadMatcBuild("matc-out/");  // a `matc -o matc-out` build directory
//   const gold = new THREE.MeshPhysicalMaterial({ roughness: 0.3 });
//   useMatcFresnel(gold, build, { material: await build.loadMaterial("gold") });
import * as THREE from "three";
import { f0TableTexture, filmTexture, sampleTrilinearly, tableTexture } from "./textures.mjs";
import { MatcWebError, anchorPattern, checkAnchors, checkAreaLights, checkIridescence, checkLayeredAreaLights, declarationsGlsl,
         matcBuildFiles, lobesGlsl, pixelSetupGlsl, rgbOf, sourceKind, basisDefine, sourceBasis } from "../matc-build.mjs";

export { MatcWebError };

// The three.js revisions whose chunks the patches below were written against and tested with
// (tests/js/check-three-engine.mjs). Others are patched too when every anchor is still there, with
// a warning; when one is not, useMatcFresnel throws.
export const kTestedThreeRevisions = ["187"];

// ---- The patches: (chunk, anchor, replacement), each anchor found exactly once. ----

// The physical material's own fragment shader (main(); the chunk onBeforeCompile receives as the
// shader's text), patched where it composes the coat.
const kMainShader = "meshphysical_frag";

// Appended to lights_physical_pars_fragment's declarations: the matc library, the tables and
// what the patched light paths read (this pixel's coefficients and preintegrated basis, set in
// main()), the lobes' functions (a coated material's from its snippet) and the image-lighting term.
const kDeclarations = (library, material, build) => `${declarationsGlsl(library, { uniforms: true, build })}
${lobesGlsl(material)}
// Image lighting: the preintegrated Fresnel sum_i c_i bbar_i with matc's multiple scattering
// (Turquin's 1 + F0 (1 - E) / E, E = bbar_0), as the CPU runtime computes it.
void matc_image_lighting( inout vec3 singleScatter, inout vec3 multiScatter ) {
	singleScatter += matc_base_preintegrated() * matc_base_compensation();
}
#ifdef MATC_METAL_ROUGH
// glTF's metal-rough model per pixel (docs/gltf.md): three's own dielectric lobe mixed with matc's
// metal by material.metalness. Set before the lights: the dielectric's F90 (three blends its F90
// with the metal's), its multiple-scattering scale (three's, with the dielectric's F0) and, under a
// matc coat, the coat's transmission at NdotV, which scales all the dielectric reflects (glTF's
// layering of a clear coat; docs/gltf.md): its specular term here, its diffuse through
// material.diffuseContribution.
float matc_dielectric_f90;
vec3 matc_dielectric_compensation;
float matc_dielectric_transmission;
#endif
`;

// What main() computes before the lights, as three.js sees the pixel.
const kPixelSetup = `${pixelSetupGlsl({
  uv: "vUv", baseColour: "diffuseColor.rgb", roughness: "material.roughness",
  ndotv: "saturate( dot( normal, isOrthographic ? vec3( 0.0, 0.0, 1.0 ) : normalize( vViewPosition ) ) )",
  coatRoughness: "material.clearcoatRoughness" })}
#ifdef MATC_METAL_ROUGH
	#if defined( IOR ) && defined( USE_SPECULAR )
		matc_dielectric_f90 = specularIntensityFactor;
	#else
		matc_dielectric_f90 = 1.0;
	#endif
	matc_dielectric_transmission = matc_coat_transmission();
	material.diffuseContribution *= matc_dielectric_transmission;
	matc_dielectric_compensation = vec3( matc_dielectric_transmission );
#endif
`;

// Each patch: the chunk, the exact text it replaces (found once, or the chunk changed), the text
// put there, and what it means (docs/web-engines.md lists these).
export const kPatches = [
  {
    chunk: "lights_physical_pars_fragment",
    anchor: "uniform sampler2D dfgLUT;\n",
    replacement: (library, material, build) => `uniform sampler2D dfgLUT;\n${kDeclarations(library, material, build)}`,
    what: "declarations: matc_fresnel.glsl, the tables, this pixel's coefficients (and a coated material's snippet)",
  },
  {
    chunk: "lights_physical_pars_fragment",
    anchor: "vec3 F = F_Schlick( f0, f90, dotVH ); #ifdef USE_IRIDESCENCE",
    replacement: () =>
      "#ifdef MATC_METAL_ROUGH\n" +
      "\tvec3 F = matc_metal_rough( F_Schlick( material.specularColor, matc_dielectric_f90, dotVH ) * matc_dielectric_compensation, " +
      "matc_base_fresnel( dotVH ) * matc_base_compensation(), material.metalness );\n" +
      "#else\n" +
      "\tvec3 F = matc_base_fresnel( dotVH );\n" +
      "#endif\n\n\t#ifdef USE_IRIDESCENCE\n",
    what: "punctual lights: F_Schlick(f0, f90, dotVH) in BRDF_GGX becomes matc_fresnel(c, dotVH) (a coated " +
          "material's base lobe: the metal through the coat); with metalRough, three's dielectric Schlick curve and " +
          "matc's metal mixed by metalness (matc_metal_rough), each lobe with its own multiple-scattering scale",
  },
  {
    chunk: "lights_physical_pars_fragment",
    anchor: "vec3 F = F_Schlick( f0, f90, dotVH ); float V = V_GGX_SmithCorrelated( alpha, dotNL, dotNV );",
    replacement: () => "#ifdef MATC_COATED\n\t\tvec3 F = vec3( matc_coat_lobe_fresnel( dotVH ) );\n#else\n" +
                       "\t\tvec3 F = F_Schlick( f0, f90, dotVH );\n#endif\n" +
                       "\t\tfloat V = V_GGX_SmithCorrelated( alpha, dotNL, dotNV );\n",
    what: "a coated material's coat lobe, punctual lights: F_Schlick(0.04, 1, dotVH) in BRDF_GGX_Clearcoat " +
          "becomes the coat's fitted dielectric Fresnel times its weight",
  },
  {
    chunk: "lights_physical_pars_fragment",
    anchor: "clearcoatSpecularIndirect += clearcoatRadiance * EnvironmentBRDF( geometryClearcoatNormal, " +
            "geometryViewDir, material.clearcoatF0, material.clearcoatF90, material.clearcoatRoughness );",
    replacement: () =>
      "#ifdef MATC_COATED\n" +
      "\t\tclearcoatSpecularIndirect += clearcoatRadiance * matc_coat_lobe_preintegrated();\n" +
      "#else\n" +
      "\t\tclearcoatSpecularIndirect += clearcoatRadiance * EnvironmentBRDF( geometryClearcoatNormal, geometryViewDir, " +
      "material.clearcoatF0, material.clearcoatF90, material.clearcoatRoughness );\n" +
      "#endif\n",
    what: "a coated material's coat lobe, image lighting: three's Schlick DFG term becomes the coat's " +
          "preintegrated Fresnel (matc_lut at the coat's roughness) times its weight",
  },
  {
    chunk: "lights_physical_pars_fragment",
    anchor: "vec3 fresnelClearcoat = material.clearcoatF0 * t2Clearcoat.x + ( material.clearcoatF90 - " +
            "material.clearcoatF0 ) * t2Clearcoat.y; clearcoatSpecularDirect += lightColor * fresnelClearcoat * " +
            "LTC_Evaluate( Ncc, viewDir, position, mInvClearcoat, rectCoords );",
    replacement: () =>
      "#if defined( MATC_COATED ) && defined( MATC_ENGINE_LTC )\n" +
      "\t\t\tclearcoatSpecularDirect += lightColor * matc_coat_lobe_preintegrated() * LTC_Evaluate( Ncc, viewDir, position, mInvClearcoat, rectCoords );\n" +
      "#elif defined( MATC_COATED )\n" +
      "\t\t\tvec4 matc_coat_ltc_texel = texture2D( matc_ltc, matc_ltc_texcoord( saturate( dot( Ncc, viewDir ) ), material.clearcoatRoughness ) );\n" +
      "\t\t\tif ( matc_lit ) clearcoatSpecularDirect += lightColor * matc_coat_lobe_preintegrated() * matc_ltc_quad_integral( " +
      "matc_ltc_transform( Ncc, viewDir, matc_coat_ltc_texel ), position, rectCoords[ 0 ], rectCoords[ 1 ], rectCoords[ 2 ], rectCoords[ 3 ] );\n" +
      "#else\n" +
      "\t\t\tvec3 fresnelClearcoat = material.clearcoatF0 * t2Clearcoat.x + ( material.clearcoatF90 - material.clearcoatF0 ) * t2Clearcoat.y;\n" +
      "\t\t\tclearcoatSpecularDirect += lightColor * fresnelClearcoat * LTC_Evaluate( Ncc, viewDir, position, mInvClearcoat, rectCoords );\n" +
      "#endif\n",
    what: "a coated material's coat lobe, rect area lights: Hill's Schlick LTC Fresnel becomes the coat's " +
          "preintegrated Fresnel times its weight, with matc's LTC at the coat's roughness (three's LTC_1 " +
          "shape with areaLights: \"engine\")",
  },
  {
    chunk: "lights_physical_pars_fragment",
    anchor: "\t\tcomputeMultiscattering( material.dfg, material.diffuseColor, material.specularF90, " +
            "singleScatteringMetallic, multiScatteringMetallic );\n",
    replacement: () => "\t\tmatc_image_lighting( singleScatteringMetallic, multiScatteringMetallic );\n",
    what: "image lighting: the two-channel DFG table and Fdez-Agüera's term become sum_i c_i bbar_i " +
          "with matc's energy compensation",
  },
  {
    chunk: "lights_physical_pars_fragment",
    anchor: "vec3 singleScattering = mix( singleScatteringDielectric, singleScatteringMetallic, material.metalness ); " +
            "vec3 multiScattering = mix( multiScatteringDielectric, multiScatteringMetallic, material.metalness );",
    replacement: () =>
      "#ifdef MATC_METAL_ROUGH\n" +
      "\tvec3 singleScattering = mix( singleScatteringDielectric * matc_dielectric_transmission, singleScatteringMetallic, material.metalness );\n" +
      "\tvec3 multiScattering = mix( multiScatteringDielectric * matc_dielectric_transmission, multiScatteringMetallic, material.metalness );\n" +
      "#else\n" +
      "\tvec3 singleScattering = mix( singleScatteringDielectric, singleScatteringMetallic, material.metalness );\n" +
      "\tvec3 multiScattering = mix( multiScatteringDielectric, multiScatteringMetallic, material.metalness );\n" +
      "#endif\n",
    what: "image lighting with metalRough under a matc coat: three's dielectric terms times the coat's transmission " +
          "at NdotV before its mix by metalness (glTF's layering of a clear coat; 1 without a coat)",
  },
  {
    chunk: "lights_physical_pars_fragment",
    anchor: "\t\treflectedLight.directSpecular += lightColor * fresnel * LTC_Evaluate( normal, viewDir, " +
            "position, mInv, rectCoords );\n",
    replacement: () =>
      "#ifdef MATC_METAL_ROUGH\n" +
      "\t\tvec3 matc_specular_before = reflectedLight.directSpecular;\n" +
      "#endif\n" +
      "#ifdef MATC_ENGINE_LTC\n" +
      "\t\treflectedLight.directSpecular += lightColor * matc_base_preintegrated() * LTC_Evaluate( normal, viewDir, position, mInv, rectCoords );\n" +
      "#else\n" +
      "\t\tvec4 matc_ltc_texel = texture2D( matc_ltc, matc_ltc_texcoord( saturate( dot( normal, viewDir ) ), roughness ) );\n" +
      "\t\tbool matc_lit = dot( cross( rectCoords[ 1 ] - rectCoords[ 0 ], rectCoords[ 3 ] - rectCoords[ 0 ] ), position - rectCoords[ 0 ] ) >= 0.0;\n" +
      "#ifdef MATC_QUALITY_LTC\n" +
      "\t\tif ( matc_lit ) reflectedLight.directSpecular += lightColor * matc_source_ltc_quad_light_following( matc_c, matc_bbar, " +
      "matc_ltc_texel, roughness, normal, viewDir, position, rectCoords[ 0 ], rectCoords[ 1 ], rectCoords[ 2 ], rectCoords[ 3 ] );\n" +
      "#else\n" +
      "\t\tif ( matc_lit ) reflectedLight.directSpecular += lightColor * matc_base_preintegrated() * matc_ltc_quad_integral( " +
      "matc_ltc_transform( normal, viewDir, matc_ltc_texel ), position, rectCoords[ 0 ], rectCoords[ 1 ], rectCoords[ 2 ], rectCoords[ 3 ] );\n" +
      "#endif\n" +
      "#endif\n" +
      "#ifdef MATC_METAL_ROUGH\n" +
      "\t\treflectedLight.directSpecular = matc_specular_before + matc_metal_rough( lightColor * ( material.specularColor * t2.x + " +
      "( matc_dielectric_f90 - material.specularColor ) * t2.y ) * matc_dielectric_transmission * LTC_Evaluate( normal, viewDir, position, mInv, rectCoords ), " +
      "reflectedLight.directSpecular - matc_specular_before, material.metalness );\n" +
      "#endif\n",
    what: "rect area lights: Hill's two-channel LTC Fresnel and the LTC_1 shape become matc's LTC " +
          "(matc_ltc) times sum_i c_i bbar_i, one-sided like three's; with areaLights: \"quality\", matc's " +
          "quality level (the shape and the Fresnel follow the light across the lobe); with areaLights: \"engine\", " +
          "three's LTC_1 shape times sum_i c_i bbar_i; with metalRough, three's own dielectric term and matc's mixed by metalness",
  },
  {
    chunk: "lights_fragment_begin",
    anchor: "\t\tmaterial.multiScatteringCompensation = 1.0 + material.specularColorBlended * " +
            "( 1.0 / EssMs - 1.0 );\n",
    replacement: () =>
      "#ifdef MATC_METAL_ROUGH\n" +
      "\t\tmatc_dielectric_compensation = ( 1.0 + material.specularColor * ( 1.0 / EssMs - 1.0 ) ) * matc_dielectric_transmission;\n" +
      "\t\tmaterial.multiScatteringCompensation = vec3( 1.0 );\n" +
      "#else\n" +
      "\t\tmaterial.multiScatteringCompensation = matc_base_compensation();\n" +
      "#endif\n",
    what: "punctual lights' multiple scattering: F0 from the coefficients, E from matc's table (with metalRough, " +
          "each lobe's scale inside BRDF_GGX's mix: three's with the dielectric's F0, matc's)",
  },
  {
    chunk: "lights_fragment_begin",
    anchor: "vec3 geometryPosition = - vViewPosition;\n",
    replacement: () => `${kPixelSetup}\nvec3 geometryPosition = - vViewPosition;\n`,
    what: "this pixel's coefficients (uniform, coefficient table or baked) and its texel of matc_lut " +
          "(and a coated material's at the coat's roughness)",
  },
  {
    chunk: kMainShader,
    anchor: "outgoingLight = outgoingLight * ( 1.0 - material.clearcoat * Fcc ) + ( clearcoatSpecularDirect + " +
            "clearcoatSpecularIndirect ) * material.clearcoat;",
    replacement: () =>
      "#ifdef MATC_COATED\n" +
      "\t\toutgoingLight = outgoingLight + clearcoatSpecularDirect + clearcoatSpecularIndirect;\n" +
      "#else\n" +
      "\t\toutgoingLight = outgoingLight * ( 1.0 - material.clearcoat * Fcc ) + ( clearcoatSpecularDirect + " +
      "clearcoatSpecularIndirect ) * material.clearcoat;\n" +
      "#endif\n",
    what: "a coated material's layering: the base lobe carries the coat's attenuation and tint and the coat " +
          "lobe its weight, so three's 1 - clearcoat Fcc and clearcoat factors go",
  },
];

// Applies the patches to the given chunks (name -> source) for `material` (build.loadMaterial's, or null for maps and bakes), throwing
// when an anchor is not found exactly once. `build`: a per-material build's aliases (basis-layers.mjs).
export function patchChunks(chunks, library, material = null, build = {}) {
  const tested = `three.js r${kTestedThreeRevisions.join(", r")}`;
  checkAnchors(`three.js r${THREE.REVISION}`, chunks, kPatches.map((patch) => ({ ...patch, source: patch.chunk })),
               tested);
  const patched = {};
  for (const patch of kPatches) {
    const source = patched[patch.chunk] ?? chunks[patch.chunk];
    patched[patch.chunk] = source.replace(anchorPattern(patch.anchor),
                                          () => `\n${patch.replacement(library, material, build)}\n`);
  }
  return patched;
}


// ---- A matc build directory as three.js textures. ----

// Reads a matc build directory (`matc -o DIR`, with glsl, json and lut among --emit; ltc for rect
// area lights, coefficient-table for textured metals) and returns what useMatcFresnel takes.
// `source`: a build directory's URL (`matc -o DIR`), or the files of materials compiled in the page
// (compiledMatcBuildFiles(matc) of ../matc-build.mjs).
export async function loadMatcBuild(source) {
  const files = await matcBuildFiles(source, "glsl");
  return { ...files, lut: tableTexture(THREE, files.lut), ltc: files.ltc && tableTexture(THREE, files.ltc),
           coefficientTable: files.coefficientTable && tableTexture(THREE, files.coefficientTable) };
}

// ---- Turning a three.js material into a matc metal. ----

function checkBuild(build) {
  if (!build || typeof build.library !== "string" || !build.lut) {
    throw new MatcWebError("useMatcFresnel needs the result of loadMatcBuild");
  }
}

// The coefficients' source: { material } (from build.loadMaterial), { schlick: { basis,
// zeroF0Coefficients } } (Schlick's curve of the material's base colour, its colour times its
// map: a textured glTF metal), { material, f0Table } (the same under an edge colour or a coat:
// the coefficients at the base colour from MATC_materials_fresnel's f0Table), { reflectivityMap, edgeTintMap } (textured: through the
// coefficient table, each map times the optional reflectivity/edgeTint colours) or { baked: {
// c2Map, c3Map, f0Map? } } (`matc bake` textures; F0 from f0Map or the material's base colour).
function sourceUniforms(build, source) {
  const kind = sourceKind(build, source);
  if (kind === "material" || kind === "schlick") {
    const rows = kind === "schlick" ? source.schlick.zeroF0Coefficients : source.material.coefficients;
    const [red, green, blue] = rows.map((row) => new THREE.Vector4(...row));
    return { define: kind === "schlick" ? "MATC_SOURCE_SCHLICK" : "MATC_SOURCE_UNIFORM",
             uniforms: { matc_red: { value: red }, matc_green: { value: green }, matc_blue: { value: blue } } };
  }
  if (kind === "f0Table") {
    return { define: "MATC_SOURCE_F0_TABLE",
             uniforms: { matc_f0_table: { value: f0TableTexture(THREE, source.f0Table) } } };
  }
  if (kind === "table") {
    const colour = (value) => new THREE.Color(...rgbOf(value));
    return { define: "MATC_SOURCE_TABLE", uv: true,
             uniforms: { matc_coefficient_table: { value: build.coefficientTable },
                         matc_reflectivity_map: { value: source.reflectivityMap },
                         matc_edge_tint_map: { value: source.edgeTintMap },
                         matc_reflectivity: { value: colour(source.reflectivity) },
                         matc_edge_tint: { value: colour(source.edgeTint) } } };
  }
  const { c2Map, c3Map, f0Map } = source.baked;
  sampleTrilinearly(THREE, [c2Map, c3Map, f0Map]);
  const uniforms = { matc_c2_map: { value: c2Map }, matc_c3_map: { value: c3Map } };
  if (f0Map) uniforms.matc_f0_map = { value: f0Map };
  return { define: "MATC_SOURCE_BAKED", uv: true, f0: Boolean(f0Map), uniforms };
}

// Makes `material` (MeshStandardMaterial or MeshPhysicalMaterial) a matc metal: metalness 1, its
// Fresnel in every light path from `source` (see sourceUniforms). options.metalRough: glTF's
// metal-rough model per pixel instead (docs/gltf.md): the material keeps its metalness and
// metalnessMap, and matc's metal replaces three's metal lobe only, mixed by the pixel's metalness
// with three's own dielectric in every light path (under a matc coat, the dielectric seen through
// it as glTF layers a clear coat). Returns the material; its
// userData.matc.uniforms can be changed later (e.g. another compiled material's coefficients).
// options.areaLights: "matc" (default: matc's LTC table and horizon-clipped integral, checked
// against the CPU runtime), "quality" (the same with matc's quality level: the lobe's shape and
// the Fresnel follow the light across the lobe, docs/ltc.md; a quarter more per light) or "engine"
// (three's LTC shape with matc's Fresnel: cheaper; docs/web-engines.md measures them).
// options.bareFilm: `source` is the bare metal that matc compiled from the material's film (index 1,
// 0 nm or no coverage: docs/thin-film.md); it takes the place of three's iridescence, which is
// switched off, as a filmed metal does (the glTF loaders set it).
export function useMatcFresnel(material, build, source, { areaLights = "matc", metalRough = false, bareFilm = false } = {}) {
  checkAreaLights(areaLights);
  checkBuild(build);
  if (!material?.isMeshStandardMaterial) {
    throw new MatcWebError("useMatcFresnel takes a MeshStandardMaterial or MeshPhysicalMaterial");
  }
  const film = source?.material?.film;
  const replacesIridescence = checkIridescence(material.iridescence > 0, film, bareFilm);
  if (!kTestedThreeRevisions.includes(THREE.REVISION)) {
    console.warn(`matc-three: three.js r${THREE.REVISION} is untested (tested: r` +
                 `${kTestedThreeRevisions.join(", r")}); its chunks still match the patches`);
  }
  const { define, uv, f0, uniforms } = sourceUniforms(build, source);
  const coat = source.material?.coat;
  if (coat && !material.isMeshPhysicalMaterial) {
    throw new MatcWebError(`${source.material.name} is coated: its coat lobe needs a MeshPhysicalMaterial`);
  }
  checkLayeredAreaLights(source.material, areaLights);
  // Checked now, so that a changed engine fails here and not at the first frame.
  const { [kMainShader]: main, ...chunks } = patchChunks(THREE.ShaderChunk, build.library, source.material, build);
  Object.assign(uniforms, { matc_lut: { value: build.lut }, matc_ltc: { value: build.ltc ?? build.lut } });
  if (film) {
    // A filmed metal: its own table.
    uniforms.matc_film_table = { value: filmTexture(THREE, film.table) };
  }
  // matc's film (or the bare metal a film of index 1 is) in place of three's iridescence.
  if (replacesIridescence) material.iridescence = 0;
  if (!metalRough) {
    material.metalness = 1;
    material.metalnessMap = null;
  }
  material.defines = { ...(material.defines ?? {}), [define]: "" };
  if (metalRough) material.defines.MATC_METAL_ROUGH = "";
  if (uv) material.defines.USE_UV = "";
  if (f0) material.defines.MATC_BAKED_F0 = "";
  if (film) material.defines.MATC_FILMED = "";
  // A per-material build: the source's basis' functions (and its layer of the table).
  const layerDefine = basisDefine(build, sourceBasis(build, source));
  if (layerDefine) material.defines[layerDefine] = "";
  if (areaLights === "engine") material.defines.MATC_ENGINE_LTC = "";
  if (areaLights === "quality") material.defines.MATC_QUALITY_LTC = "";
  if (coat) {
    // The coat's lobe and layering are the compiled material's (weight, index, colour and
    // roughness); three's clearcoat only switches its coat light paths on.
    material.defines.MATC_COATED = "";
    material.clearcoat = 1;
    material.clearcoatRoughness = coat.roughness;
  }
  material.userData.matc = { uniforms, source };
  material.onBeforeCompile = (shader) => {
    if (!build.ltc && areaLights !== "engine" && shader.numRectAreaLights > 0) {
      throw new MatcWebError(`${build.url}: rect area lights need matc's LTC table; compile with --emit ltc`);
    }
    if (shader.fragmentShader !== THREE.ShaderChunk[kMainShader]) {
      throw new MatcWebError(`three.js r${THREE.REVISION}: the material's fragment shader is not ${kMainShader}`);
    }
    shader.fragmentShader = main;
    for (const [name, text] of Object.entries(chunks)) {
      const include = `#include <${name}>`;
      if (!shader.fragmentShader.includes(include)) {
        throw new MatcWebError(`three.js r${THREE.REVISION}: the physical material's fragment shader ` +
                                 `no longer includes ${name}`);
      }
      shader.fragmentShader = shader.fragmentShader.replace(include, () => text);
    }
    Object.assign(shader.uniforms, uniforms);
  };
  // A coated material's constants are in its snippet: one program per snippet (not per name: a
  // material recompiled in the page under the same name with another coat needs its own).
  material.customProgramCacheKey = () =>
    `matc:${define}:${areaLights}:${metalRough}:${Boolean(film)}:${build.url}:${coat ? source.material.coat.snippet : ""}`;
  material.needsUpdate = true;
  return material;
}
