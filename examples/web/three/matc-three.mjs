// matc's Fresnel inside three.js's own physical material: a MeshStandardMaterial or
// MeshPhysicalMaterial becomes a matc metal in every light path the engine has (punctual lights,
// image lighting with its multiple scattering, rect area lights), with the rest of the engine
// (shadows, fog, tone mapping, maps, clearcoat) untouched. Patched at run time from the engine's
// own shader chunks; a chunk that changed makes it throw, never render wrongly. README.md says
// how to use it and docs/web-engines.md what each patch replaces.
//
//   import { loadMatcBuild, useMatcFresnel } from "./matc-three.mjs";
//   const build = await loadMatcBuild("matc-out/");  // a `matc -o matc-out` build directory
//   const gold = new THREE.MeshPhysicalMaterial({ roughness: 0.3 });
//   useMatcFresnel(gold, build, { material: await build.loadMaterial("gold") });
import * as THREE from "three";
import { sampleTrilinearly, tableTexture } from "./textures.mjs";
import { MatcWebError, anchorPattern, checkAnchors, checkAreaLights, declarationsGlsl, loadMatcBuildFiles,
         pixelSetupGlsl, rgbOf, sourceKind } from "../matc-build.mjs";

export { MatcWebError };

// The three.js revisions whose chunks the patches below were written against and tested with
// (tests/js/check-three-engine.mjs). Others are patched too when every anchor is still there, with
// a warning; when one is not, useMatcFresnel throws.
export const kTestedThreeRevisions = ["187"];

// ---- The patches: (chunk, anchor, replacement), each anchor found exactly once. ----

// Appended to lights_physical_pars_fragment's declarations: the matc library, the tables and
// what the patched light paths read (this pixel's coefficients and preintegrated basis, set in
// main()), and the image-lighting term.
const kDeclarations = (library) => `${declarationsGlsl(library, { uniforms: true })}
// Image lighting: the preintegrated Fresnel sum_i c_i bbar_i with matc's multiple scattering
// (Turquin's 1 + F0 (1 - E) / E, E = bbar_0), as the CPU runtime computes it.
void matc_image_lighting( inout vec3 singleScatter, inout vec3 multiScatter ) {
	singleScatter += matc_fresnel_preintegrated( matc_c, matc_bbar ) * matc_energy_compensation( matc_c, matc_bbar );
}
`;

// What main() computes before the lights, as three.js sees the pixel.
const kPixelSetup = pixelSetupGlsl({
  uv: "vUv", baseColour: "diffuseColor.rgb", roughness: "material.roughness",
  ndotv: "saturate( dot( normal, isOrthographic ? vec3( 0.0, 0.0, 1.0 ) : normalize( vViewPosition ) ) )" });

// Each patch: the chunk, the exact text it replaces (found once, or the chunk changed), the text
// put there, and what it means (docs/web-engines.md lists these).
export const kPatches = [
  {
    chunk: "lights_physical_pars_fragment",
    anchor: "uniform sampler2D dfgLUT;\n",
    replacement: (library) => `uniform sampler2D dfgLUT;\n${kDeclarations(library)}`,
    what: "declarations: matc_fresnel.glsl, the tables, this pixel's coefficients",
  },
  {
    chunk: "lights_physical_pars_fragment",
    anchor: "vec3 F = F_Schlick( f0, f90, dotVH ); #ifdef USE_IRIDESCENCE",
    replacement: () => "\tvec3 F = matc_fresnel( matc_c, dotVH );\n\n\t#ifdef USE_IRIDESCENCE\n",
    what: "punctual lights: F_Schlick(f0, f90, dotVH) in BRDF_GGX becomes matc_fresnel(c, dotVH)",
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
    anchor: "\t\treflectedLight.directSpecular += lightColor * fresnel * LTC_Evaluate( normal, viewDir, " +
            "position, mInv, rectCoords );\n",
    replacement: () =>
      "#ifdef MATC_ENGINE_LTC\n" +
      "\t\treflectedLight.directSpecular += lightColor * matc_fresnel_preintegrated( matc_c, matc_bbar ) * LTC_Evaluate( normal, viewDir, position, mInv, rectCoords );\n" +
      "#else\n" +
      "\t\tvec4 matc_ltc_texel = texture2D( matc_ltc, matc_ltc_texcoord( saturate( dot( normal, viewDir ) ), roughness ) );\n" +
      "\t\tbool matc_lit = dot( cross( rectCoords[ 1 ] - rectCoords[ 0 ], rectCoords[ 3 ] - rectCoords[ 0 ] ), position - rectCoords[ 0 ] ) >= 0.0;\n" +
      "#ifdef MATC_QUALITY_LTC\n" +
      "\t\tif ( matc_lit ) reflectedLight.directSpecular += lightColor * matc_ltc_quad_light_following( matc_c, matc_bbar, " +
      "matc_ltc_texel, roughness, normal, viewDir, position, rectCoords[ 0 ], rectCoords[ 1 ], rectCoords[ 2 ], rectCoords[ 3 ] );\n" +
      "#else\n" +
      "\t\tif ( matc_lit ) reflectedLight.directSpecular += lightColor * matc_ltc_quad_light( matc_c, matc_bbar, matc_ltc_texel, " +
      "normal, viewDir, position, rectCoords[ 0 ], rectCoords[ 1 ], rectCoords[ 2 ], rectCoords[ 3 ] );\n" +
      "#endif\n" +
      "#endif\n",
    what: "rect area lights: Hill's two-channel LTC Fresnel and the LTC_1 shape become matc's LTC " +
          "(matc_ltc) times sum_i c_i bbar_i, one-sided like three's; with areaLights: \"quality\", matc's " +
          "quality level (the shape and the Fresnel follow the light across the lobe); with areaLights: \"engine\", " +
          "three's LTC_1 shape times sum_i c_i bbar_i",
  },
  {
    chunk: "lights_fragment_begin",
    anchor: "\t\tmaterial.multiScatteringCompensation = 1.0 + material.specularColorBlended * " +
            "( 1.0 / EssMs - 1.0 );\n",
    replacement: () => "\t\tmaterial.multiScatteringCompensation = matc_energy_compensation( matc_c, matc_bbar );\n",
    what: "punctual lights' multiple scattering: F0 from the coefficients, E from matc's table",
  },
  {
    chunk: "lights_fragment_begin",
    anchor: "vec3 geometryPosition = - vViewPosition;\n",
    replacement: () => `${kPixelSetup}\nvec3 geometryPosition = - vViewPosition;\n`,
    what: "this pixel's coefficients (uniform, coefficient table or baked) and its texel of matc_lut",
  },
];

// Applies the patches to the given chunks (name -> source), throwing when an anchor is not found
// exactly once.
export function patchChunks(chunks, library) {
  const tested = `three.js r${kTestedThreeRevisions.join(", r")}`;
  checkAnchors(`three.js r${THREE.REVISION}`, chunks, kPatches.map((patch) => ({ ...patch, source: patch.chunk })),
               tested);
  const patched = {};
  for (const patch of kPatches) {
    const source = patched[patch.chunk] ?? chunks[patch.chunk];
    patched[patch.chunk] = source.replace(anchorPattern(patch.anchor), () => `\n${patch.replacement(library)}\n`);
  }
  return patched;
}

// ---- A matc build directory as three.js textures. ----

// Reads a matc build directory (`matc -o DIR`, with glsl, json and lut among --emit; ltc for rect
// area lights, coefficient-table for textured metals) and returns what useMatcFresnel takes.
export async function loadMatcBuild(url) {
  const files = await loadMatcBuildFiles(url);
  return { ...files, lut: tableTexture(THREE, files.lut), ltc: files.ltc && tableTexture(THREE, files.ltc),
           coefficientTable: files.coefficientTable && tableTexture(THREE, files.coefficientTable) };
}

// ---- Turning a three.js material into a matc metal. ----

function checkBuild(build) {
  if (!build || typeof build.library !== "string" || !build.lut) {
    throw new MatcWebError("useMatcFresnel needs the result of loadMatcBuild");
  }
}

// The coefficients' source: { material } (from build.loadMaterial), { reflectivityMap,
// edgeTintMap } (textured: through the coefficient table, each map times the optional
// reflectivity/edgeTint colours) or { baked: { c2Map, c3Map, f0Map? } } (`matc bake` textures;
// F0 from f0Map or the material's base colour).
function sourceUniforms(build, source) {
  const kind = sourceKind(build, source);
  if (kind === "material") {
    const [red, green, blue] = source.material.coefficients.map((row) => new THREE.Vector4(...row));
    return { define: "MATC_SOURCE_UNIFORM",
             uniforms: { matc_red: { value: red }, matc_green: { value: green }, matc_blue: { value: blue } } };
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
// Fresnel in every light path from `source` (see sourceUniforms). Returns the material; its
// userData.matc.uniforms can be changed later (e.g. another compiled material's coefficients).
// options.areaLights: "matc" (default: matc's LTC table and horizon-clipped integral, checked
// against the CPU runtime), "quality" (the same with matc's quality level: the lobe's shape and
// the Fresnel follow the light across the lobe, docs/ltc.md; a quarter more per light) or "engine"
// (three's LTC shape with matc's Fresnel: cheaper; docs/web-engines.md measures them).
export function useMatcFresnel(material, build, source, { areaLights = "matc" } = {}) {
  checkAreaLights(areaLights);
  checkBuild(build);
  if (!material?.isMeshStandardMaterial) {
    throw new MatcWebError("useMatcFresnel takes a MeshStandardMaterial or MeshPhysicalMaterial");
  }
  if (material.iridescence > 0) {
    throw new MatcWebError("iridescence replaces the base Fresnel; it cannot be combined with matc's");
  }
  if (!kTestedThreeRevisions.includes(THREE.REVISION)) {
    console.warn(`matc-three: three.js r${THREE.REVISION} is untested (tested: r` +
                 `${kTestedThreeRevisions.join(", r")}); its chunks still match the patches`);
  }
  // Checked now, so that a changed engine fails here and not at the first frame.
  const chunks = patchChunks(THREE.ShaderChunk, build.library);
  const { define, uv, f0, uniforms } = sourceUniforms(build, source);
  Object.assign(uniforms, { matc_lut: { value: build.lut }, matc_ltc: { value: build.ltc ?? build.lut } });
  material.metalness = 1;
  material.metalnessMap = null;
  material.defines = { ...(material.defines ?? {}), [define]: "" };
  if (uv) material.defines.USE_UV = "";
  if (f0) material.defines.MATC_BAKED_F0 = "";
  if (areaLights === "engine") material.defines.MATC_ENGINE_LTC = "";
  if (areaLights === "quality") material.defines.MATC_QUALITY_LTC = "";
  material.userData.matc = { uniforms, source };
  material.onBeforeCompile = (shader) => {
    if (!build.ltc && areaLights !== "engine" && shader.numRectAreaLights > 0) {
      throw new MatcWebError(`${build.url}: rect area lights need matc's LTC table; compile with --emit ltc`);
    }
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
  material.customProgramCacheKey = () => `matc:${define}:${areaLights}:${build.url}`;
  material.needsUpdate = true;
  return material;
}
