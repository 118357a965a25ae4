// matc's Fresnel in three.js's WebGPURenderer: a MeshStandardNodeMaterial or
// MeshPhysicalNodeMaterial whose lighting model is three's PhysicalLightingModel with matc's Fresnel
// in punctual lights, image lighting (with matc's energy compensation) and rect area lights (matc's
// LTC table and integral times sum_i c_i bbar_i, or three's LTC shape times it). The Fresnel is the WGSL library matc writes
// (matc_fresnel.wgsl) called through wgslFn, so every basis works as compiled; coefficients from a
// compiled material, from maps through the coefficient table, from `matc bake` textures, or from
// the base colour (a textured glTF metal: Schlick's curve, or its F0 table, under a coat too). A coated
// matc material's coat lobe replaces three's clearcoat.
//
//   import { loadMatcBuild, useMatcFresnel } from "matc/three/webgpu";
//   const build = await loadMatcBuild("matc-out/");
//   const gold = useMatcFresnel(new THREE.MeshPhysicalNodeMaterial({ roughness: 0.3 }), build,
//                               { material: await build.loadMaterial("gold") });
import * as THREE from "three/webgpu";
import { BRDF_GGX, BRDF_Lambert, F_Schlick, LTC_Evaluate, LTC_Uv, clearcoatNormalView, clearcoatRoughness,
         diffuseColor, diffuseContribution, float, mat3, ivec2, metalness, normalView, positionView,
         positionViewDirection, roughness, specularColor, specularF90, step, texture, textureLoad, uniform, uv,
         vec3, vec4, wgsl, wgslFn } from "three/tsl";
import { f0TableTexture, filmTexture, sampleTrilinearly, tableTexture } from "./textures.mjs";
import { MatcWebError, basisSuffix, buildBases, checkAnchors, checkAreaLights, checkIridescence, checkLayeredAreaLights,
         matcBuildFiles, rgbOf, sourceBasis, sourceKind } from "../matc-build.mjs";

export { MatcWebError };

// The three.js revisions whose PhysicalLightingModel the subclass below was written against and
// tested with (tests/js/check-three-webgpu-engine.mjs).
export const kTestedThreeRevisions = ["187"];

// What the subclass relies on in three's PhysicalLightingModel, checked in its methods' source
// text: a three.js where one changed makes useMatcFresnel throw.
const kOverrides = [
  { source: "start", anchor: "this.multiScatteringCompensation =",
    what: "punctual lights' multiple scattering: matc_energy_compensation instead of three's" },
  { source: "start", anchor: "this.computeMultiscattering(",
    what: "image lighting (dielectric layer): sum_i c_i bbar_i with matc's compensation" },
  { source: "indirectSpecular", anchor: "this.computeMultiscattering( singleScatteringMetallic, multiScatteringMetallic,",
    what: "image lighting (metal): sum_i c_i bbar_i with matc's compensation" },
  { source: "direct", anchor: "direct( { lightDirection, lightColor, reflectedLight }",
    what: "punctual lights: three's GGX with matc's F(v.h)" },
  { source: "directRectArea", anchor: "directRectArea( { lightColor, lightPosition, halfWidth, halfHeight, reflectedLight, ltc_1",
    what: "rect area lights: matc's LTC (or three's LTC shape) times sum_i c_i bbar_i" },
  // A coated material: three's coat terms are left out while the lighting model's own run (they
  // are switched on `this.clearcoat`), and matc's coat lobe and layering are added instead.
  { source: "indirectSpecular", anchor: "if ( this.clearcoat === true ) { const dotNVcc = clearcoatNormalView.dot( positionViewDirection ).clamp(); const clearcoatEnv = EnvironmentBRDF(",
    what: "a coated material's image lighting: the coat lobe's preintegrated Fresnel instead of three's Schlick DFG term" },
  { source: "finish", anchor: "if ( this.clearcoat === true ) { const dotNVcc = clearcoatNormalView.dot( positionViewDirection ).clamp(); const Fcc = F_Schlick(",
    what: "a coated material's layering: the base lobe carries the coat's attenuation and tint, so three's 1 - clearcoat Fcc goes" },
];

function checkLightingModel() {
  const prototype = THREE.PhysicalLightingModel?.prototype ?? {};
  const sources = Object.fromEntries(kOverrides.map(({ source }) =>
    [source, typeof prototype[source] === "function" ? prototype[source].toString() : undefined]));
  if (!kTestedThreeRevisions.includes(THREE.REVISION)) {
    console.warn(`matc: three.js r${THREE.REVISION} is untested with WebGPURenderer (tested: r` +
                 `${kTestedThreeRevisions.join(", r")}); its lighting model still matches`);
  }
  checkAnchors(`three.js r${THREE.REVISION} (WebGPURenderer)`, sources, kOverrides,
               `three.js r${kTestedThreeRevisions.join(", r")}`);
}

// Reads a matc build directory (`matc -o DIR`, with wgsl, json and lut among --emit; ltc for rect
// area lights, coefficient-table for textured metals).
// `source`: a build directory's URL (`matc -o DIR`), or the files of materials compiled in the page
// (compiledMatcBuildFiles(matc, { language: "wgsl" }) of ../matc-build.mjs).
export async function loadMatcBuild(source) {
  const files = await matcBuildFiles(source, "wgsl");
  const lut = tableTexture(THREE, files.lut);
  const ltc = files.ltc && tableTexture(THREE, files.ltc);
  const coefficientTable = files.coefficientTable && tableTexture(THREE, files.coefficientTable);
  // The library once, and the entry points the lighting model calls (coefficients as three rows).
  const library = wgsl(files.library);
  const rows = "red: vec4f, green: vec4f, blue: vec4f";
  const coefficients = "MatcFresnelCoefficients(red, green, blue)";
  const entry = (name, parameters, result, call) =>
    wgslFn(`fn ${name}(${rows}, ${parameters}) -> ${result} { return ${call}; }`, [library]);
  const functions = {

    preintegrated: entry("matc_three_preintegrated", "bbar: vec4f", "vec3f",
                         `matc_fresnel_preintegrated(${coefficients}, bbar)`),
    compensation: entry("matc_three_compensation", "bbar: vec4f", "vec3f",
                        `matc_energy_compensation(${coefficients}, bbar)`),

    // Textured metals: one channel's c_0..c_3 from its r and the coefficient table's texel.
    tableTexcoord: wgslFn("fn matc_three_table_texcoord(r: f32, g: f32) -> vec2f { " +
                          "return matc_coefficient_table_texcoord(r, g); }", [library]),
    channel: wgslFn("fn matc_three_channel(r: f32, texel: vec2f) -> vec4f { " +
                    "return matc_channel_coefficients(r, texel); }", [library]),
  };
  // A textured metal of Schlick's curve: each channel's row of matc_coefficients_from_f0 on the
  // curve's rows at F0 = 0.
  for (const channel of ["red", "green", "blue"]) {
    functions[`fromF0${channel}`] = entry(`matc_three_from_f0_${channel}`, "f0: vec3f", "vec4f",
                                          `matc_coefficients_from_f0(${coefficients}, f0).${channel}`);
  }
  // A textured metal's F0 table: the entry left of a channel's F0, and each channel's row of
  // matc_coefficients_from_f0_entries on the entries left and right of its F0 (as the library's
  // MATC_COEFFICIENTS_FROM_F0_TABLE reads them).
  functions.f0TableLeft = wgslFn("fn matc_three_f0_table_left(f0: f32) -> i32 { " +
                                 "return matc_f0_table_left(matc_f0_table_position(f0)); }", [library]);
  const sides = "left_red: vec4f, left_green: vec4f, left_blue: vec4f, right_red: vec4f, right_green: vec4f, " +
                "right_blue: vec4f";
  // Under a coat, the metal seen from the coat likewise (matc_under_coat_from_f0_entries).
  for (const channel of ["red", "green", "blue"]) {
    for (const [key, from] of [["fromF0Entries", "coefficients"], ["fromF0UnderCoat", "under_coat"]]) {
      functions[`${key}${channel}`] = wgslFn(
          `fn matc_three_${from}_from_f0_entries_${channel}(f0: vec3f, ${sides}) -> vec4f { return ` +
          `matc_${from}_from_f0_entries(f0, MatcFresnelCoefficients(left_red, left_green, left_blue), ` +
          `MatcFresnelCoefficients(right_red, right_green, right_blue)).${channel}; }`, [library]);
    }
  }
  // Filmed metals: where their own table's F and Fbar texels lie (docs/thin-film.md).
  functions.filmFresnelTexcoord = wgslFn("fn matc_three_film_fresnel_texcoord(mu: f32) -> vec2f { " +
                                         "return matc_film_fresnel_texcoord(mu); }", [library]);
  functions.filmPreintegratedTexcoord = wgslFn("fn matc_three_film_preintegrated_texcoord(ndotv: f32, roughness: f32) " +
                                               "-> vec2f { return matc_film_preintegrated_texcoord(ndotv, roughness); }",
                                               [library]);
  if (ltc) {
    // Rect area lights (the library has matc's LTC functions when the build wrote its table).
    functions.ltcTexcoord = wgslFn("fn matc_three_ltc_texcoord(ndotv: f32, roughness: f32) -> vec2f { " +
                                   "return matc_ltc_texcoord(ndotv, roughness); }", [library]);
    // The LTC integral of a quad (bare and coated lobes multiply it by their preintegrated F, as
    // matc_ltc_quad_light does).
    functions.quadIntegral = wgslFn("fn matc_three_quad_integral(ltc: vec4f, N: vec3f, V: vec3f, P: vec3f, " +
                                    "q0: vec3f, q1: vec3f, q2: vec3f, q3: vec3f) -> f32 { return " +
                                    "matc_ltc_quad_integral(matc_ltc_transform(N, V, ltc), P, q0, q1, q2, q3); }",
                                    [library]);
  }
  // What a material's basis changes (its F, its layer of the table, its quality-level area light):
  // the first basis' for `functions`, each further layer's of a per-material build (matc --basis
  // auto) by basis in functionsByBasis.
  const basisFunctions = (basis) => {
    const suffix = basisSuffix(files, basis);
    const own = {
      fresnel: entry(`matc_three_fresnel${suffix}`, "mu: f32", "vec3f", `matc_fresnel${suffix}(${coefficients}, mu)`),
      lutTexcoord: wgslFn(`fn matc_three_lut_texcoord${suffix}(ndotv: f32, roughness: f32) -> vec2f { ` +
                          `return matc_lut_texcoord${suffix}(ndotv, roughness); }`, [library]),
    };
    if (ltc) {
      own.quadLightFollowing = entry(
          `matc_three_quad_light_following${suffix}`, "bbar: vec4f, ltc: vec4f, roughness: f32, N: vec3f, " +
          "V: vec3f, P: vec3f, q0: vec3f, q1: vec3f, q2: vec3f, q3: vec3f", "vec3f",
          `matc_ltc_quad_light_following${suffix}(${coefficients}, bbar, ltc, roughness, N, V, P, q0, q1, q2, q3)`);
    }
    return own;
  };
  const bases = buildBases(files);
  Object.assign(functions, basisFunctions(bases[0]));
  const functionsByBasis = Object.fromEntries(
      bases.slice(1).map((basis) => [basis, { ...functions, ...basisFunctions(basis) }]));
  const loadMaterial = files.loadMaterial;
  // A coated material's lobes: its own snippet (<name>.wgsl) through wgslFn. The base lobe's
  // take the coefficient rows in air and under the coat (layerRows): the material's own, or a
  // textured metal's per pixel from its F0 table (the snippet's matc_fresnel_textured_<name>).
  const withCoatFunctions = (material) => {
    if (!material.coat) return material;
    const snippet = wgsl(material.coat.snippet);
    const name = material.name;
    const fn = (code) => wgslFn(code, [library, snippet]);
    const rows = (prefix) => ["red", "green", "blue"].map((channel) => `${prefix}_${channel}: vec4f`).join(", ");
    const struct = (prefix) => `MatcFresnelCoefficients(${prefix}_red, ${prefix}_green, ${prefix}_blue)`;
    const coatLobe = {
      coatFresnel: fn(`fn matc_three_coat_fresnel_${name}(mu: f32) -> f32 { return matc_coat_fresnel_${name}(mu); }`),
      coatPreintegrated: fn(`fn matc_three_coat_preintegrated_${name}(coat_bbar: vec4f) -> f32 ` +
                            `{ return matc_coat_fresnel_preintegrated_${name}(coat_bbar); }`),
      transmission: fn(`fn matc_three_coat_transmission_${name}(ndotv: f32) -> f32 ` +
                       `{ return matc_coat_transmission_${name}(ndotv); }`),
    };
    // A film under the coat (docs/thin-film.md): its table is the base lobe; the snippet has the
    // coat lobe's functions only.
    if (material.film) {
      material.coat.functions = coatLobe;
      return material;
    }
    material.coat.functions = {
      ...coatLobe,
      baseFresnel: fn(`fn matc_three_base_fresnel_${name}(${rows("in_air")}, ${rows("under_coat")}, mu: f32) -> vec3f ` +
                      `{ return matc_fresnel_textured_${name}(${struct("in_air")}, ${struct("under_coat")}, mu); }`),
      basePreintegrated: fn(`fn matc_three_base_preintegrated_${name}(${rows("in_air")}, ${rows("under_coat")}, ` +
                            "bbar: vec4f, coat_bbar: vec4f, ndotv: f32) -> vec3f { return " +
                            `matc_fresnel_preintegrated_textured_${name}(${struct("in_air")}, ${struct("under_coat")}, ` +
                            "bbar, coat_bbar, ndotv); }"),
    };
    return material;
  };
  // withCoatFunctions: for a coated material made elsewhere with this build's WGSL snippet (a glTF
  // metal's from its MATC_materials_fresnel, ./matc-gltf-webgpu.mjs).
  return { ...files, lut, ltc, coefficientTable, functions, functionsByBasis, withCoatFunctions,
           async loadMaterial(name) { return withCoatFunctions(await loadMaterial(name)); } };
}

// A coated material's base-lobe arguments: the rows in air and under the coat, by parameter name.
function layerRows({ red, green, blue }, { red: underRed, green: underGreen, blue: underBlue }) {
  return { in_air_red: red, in_air_green: green, in_air_blue: blue,
           under_coat_red: underRed, under_coat_green: underGreen, under_coat_blue: underBlue };
}

// three's physical lighting with matc's Fresnel; `matc` holds the coefficient rows (uniform nodes),
// the table and the WGSL entry points.
class MatcPhysicalLightingModel extends THREE.PhysicalLightingModel {
  constructor(matc, material) {
    super(material.useClearcoat, material.useSheen, material.useIridescence, material.useAnisotropy,
          material.useTransmission, material.useDispersion, material.useRetroreflection,
          material.useDiffuseRoughness);
    this.matc = matc;
    // three's start() sets its own compensation and then runs the lights: reads get matc's.
    Object.defineProperty(this, "multiScatteringCompensation", {
      get: () => { this.matcTerms(); return this.matcCompensation; }, set: () => {} });
  }

  // This pixel's texel of matc_lut, its preintegrated Fresnel and energy compensation, once; for
  // a coated material also the texel at the coat's roughness and the coat lobe's preintegrated F
  // (the base's compensation is a bare metal's with the metal's F0 under the coat).
  matcTerms() {
    if (!this.matcBbar) {
      const { rows, functions, lut, coat } = this.matc;
      const ndotv = normalView.dot(positionViewDirection).clamp();
      this.matcBbar = texture(lut, functions.lutTexcoord({ ndotv, roughness })).toConst("matc_bbar");
      this.matcCompensation = functions.compensation({ ...(coat?.underCoatRows ?? rows), bbar: this.matcBbar })
          .toConst("matc_compensation");
      if (coat) {
        const coatBbar = texture(lut, functions.lutTexcoord({ ndotv, roughness: clearcoatRoughness })).toConst("matc_coat_bbar");
        this.matcCoatBbar = coatBbar;
        // A film under the coat: its table's Fbar texel is the base lobe's.
        this.matcPreintegrated = (this.matc.film
          ? texture(this.matc.film, functions.filmPreintegratedTexcoord({ ndotv, roughness })).level(0).rgb
          : coat.functions.basePreintegrated({ ...layerRows(rows, coat.underCoatRows),
                                               bbar: this.matcBbar, coat_bbar: coatBbar, ndotv }))
            .toConst("matc_preintegrated");
        this.matcCoatPreintegrated = coat.functions.coatPreintegrated({ coat_bbar: coatBbar }).toConst("matc_coat_preintegrated");
        // glTF's metal-rough model under the coat: what three's dielectric reflects times this.
        this.matcTransmission = coat.functions.transmission({ ndotv }).toConst("matc_coat_transmission");
      } else if (this.matc.film) {
        // A filmed metal: its table's Fbar texel at (NdotV, roughness).
        const coordinates = functions.filmPreintegratedTexcoord({ ndotv, roughness });
        this.matcPreintegrated = texture(this.matc.film, coordinates).level(0).rgb.toConst("matc_preintegrated");
      } else {
        this.matcPreintegrated = functions.preintegrated({ ...rows, bbar: this.matcBbar }).toConst("matc_preintegrated");
      }
    }
  }

  // A coated material: three's coat terms stay out of its own methods (they run on this.clearcoat).
  withoutThreeCoat(run) {
    if (!this.matc.coat) return run();
    this.clearcoat = false;
    try {
      return run();
    } finally {
      this.clearcoat = true;
    }
  }

  // Image lighting; a coated material's coat lobe: three's prefiltered radiance at the coat's
  // roughness times the coat's preintegrated F (its weight included).
  // With metalRough under a coat, three's dielectric terms (its (1 - metalness) share of the mix)
  // through the coat: the 1 - transmission of them taken back out (before sheen's energy scale,
  // which three applies to the whole term: a sheen over a coated metal-rough metal is off by that).
  indirectSpecular(builder) {
    this.withoutThreeCoat(() => super.indirectSpecular(builder));
    if (this.matc.coat && this.matc.metalRough) {
      const { radiance, iblIrradiance, reflectedLight } = builder.context;
      const dielectric = radiance.mul(this.singleScatteringDielectric)
        .add(this.multiScatteringDielectric.mul(iblIrradiance.mul(1 / Math.PI)));
      reflectedLight.indirectSpecular.subAssign(
        dielectric.mul(metalness.oneMinus()).mul(this.matcTransmission.oneMinus()));
    }
    if (this.matc.coat) {
      this.matcTerms();
      this.clearcoatSpecularIndirect.addAssign(this.clearcoatRadiance.mul(this.matcCoatPreintegrated));
    }
  }

  // The layering: a coated material's base lobe carries the coat's attenuation and tint and the
  // coat lobe its weight, so both are added as they are.
  finish(builder) {
    if (this.matc.coat) {
      builder.context.outgoingLight.addAssign(this.clearcoatSpecularDirect.add(this.clearcoatSpecularIndirect));
    }
    return this.withoutThreeCoat(() => super.finish(builder));
  }

  // Image lighting: sum_i c_i bbar_i times matc's compensation (as the CPU runtime computes it).
  // With metalRough (glTF's metal-rough model), the dielectric's term (start() computes it into
  // singleScatteringDielectric, before the lights) stays three's own; three mixes the two by
  // metalness. Under a coat, three's diffuse is seen through it from then on: diffuseContribution
  // times the coat's transmission.
  computeMultiscattering(singleScatter, ...rest) {
    if (this.matc.metalRough && singleScatter === this.singleScatteringDielectric) {
      super.computeMultiscattering(singleScatter, ...rest);
      if (this.matc.coat) {
        this.matcTerms();
        diffuseContribution.mulAssign(this.matcTransmission);
      }
      return;
    }
    this.matcTerms();
    singleScatter.addAssign(this.matcPreintegrated.mul(this.matcCompensation));
  }

  // Punctual lights: three's GGX with a unit Fresnel (f0 = f90 = 1) times matc's F(v.h).
  direct({ lightDirection, lightColor, reflectedLight }) {
    const dotNL = normalView.dot(lightDirection).clamp();
    const halfDir = lightDirection.add(positionViewDirection).normalize();
    const dotVH = positionViewDirection.dot(halfDir).clamp();
    const ggx = BRDF_GGX({ lightDirection, f0: vec3(1), f90: float(1), roughness });
    const { coat, film } = this.matc;
    // A filmed metal's table holds its base lobe, under a coat too.
    const fresnel = film ? texture(film, this.matc.functions.filmFresnelTexcoord({ mu: dotVH })).level(0).rgb
                  : coat ? coat.functions.baseFresnel({ ...layerRows(this.matc.rows, coat.underCoatRows), mu: dotVH })
                  : this.matc.functions.fresnel({ ...this.matc.rows, mu: dotVH });
    if (this.matc.metalRough) {
      this.metalRoughDirect({ irradiance: dotNL.mul(lightColor), ggx, fresnel, dotVH, reflectedLight });
    } else {
      reflectedLight.directSpecular.addAssign(
          dotNL.mul(lightColor).mul(ggx).mul(fresnel).mul(this.multiScatteringCompensation));
    }
    if (coat) {
      // The coat lobe: three's GGX at the coat's roughness and normal times the coat's F(v.h).
      const dotNLcc = clearcoatNormalView.dot(lightDirection).clamp();
      const ggxCoat = BRDF_GGX({ lightDirection, f0: vec3(1), f90: float(1), roughness: clearcoatRoughness,
                                 normalView: clearcoatNormalView });
      this.clearcoatSpecularDirect.addAssign(
          dotNLcc.mul(lightColor).mul(ggxCoat).mul(coat.functions.coatFresnel({ mu: dotVH })));
    }
  }

  // glTF's metal-rough model, punctual lights: three's dielectric lobe and matc's metal, each with
  // its own multiple-scattering scale, mixed by metalness as matc_metal_rough does ((1 - m) times
  // the dielectric's Schlick curve is that curve from (1 - m) F0 to specularF90 - m: three blends
  // F90 as mix(f90, 1, m)), and three's diffuse with its fresnel_mix, as its own direct() draws it;
  // under a coat, the dielectric times the coat's transmission (its diffuse: diffuseContribution).
  metalRoughDirect({ irradiance, ggx, fresnel, dotVH, reflectedLight }) {
    const dielectricCompensation = specularColor.mul(this.dfg.x.add(this.dfg.y).reciprocal().sub(1.0)).add(1.0);
    const schlick = F_Schlick({ f0: specularColor.mul(metalness.oneMinus()), f90: specularF90.sub(metalness), dotVH })
      .mul(dielectricCompensation);
    const dielectric = this.matc.coat ? schlick.mul(this.matcTransmission) : schlick;
    const metal = fresnel.mul(this.multiScatteringCompensation).mul(metalness);
    reflectedLight.directSpecular.addAssign(irradiance.mul(ggx).mul(dielectric.add(metal)));
    const F = F_Schlick({ f0: specularColor, f90: specularF90, dotVH });
    reflectedLight.directDiffuse.addAssign(irradiance.mul(BRDF_Lambert({ diffuseColor: diffuseContribution })).mul(F.oneMinus()));
  }

  // Rect area lights: matc's LTC table and horizon-clipped integral times sum_i c_i bbar_i,
  // one-sided like three's (areaLights "matc"), matc's quality level ("quality"), or three's LTC
  // shape times it ("engine").
  directRectArea({ lightColor, lightPosition, halfWidth, halfHeight, reflectedLight, ltc_1, ltc_2 }) {
    this.matcTerms();
    // The light's corners, as three's directRectArea places them, and the shading point.
    const rect = {
      N: normalView, V: positionViewDirection, P: positionView.toVar(),
      p0: lightPosition.add(halfWidth).sub(halfHeight), p1: lightPosition.sub(halfWidth).sub(halfHeight),
      p2: lightPosition.sub(halfWidth).add(halfHeight), p3: lightPosition.add(halfWidth).add(halfHeight),
    };
    if (this.matc.metalRough) {
      this.metalRoughRectArea({ lightColor, rect, reflectedLight, ltc_1, ltc_2 });
      return;
    }
    this.matcRectArea({ lightColor, rect, reflectedLight, ltc_1 });
  }

  // glTF's metal-rough model, rect area lights: three's dielectric term (Hill's LTC Fresnel with
  // the dielectric's F0 and F90, weighted by 1 - metalness as in metalRoughDirect) and its diffuse,
  // as its own directRectArea draws them, beside matc's metal (matcRectArea) weighted by metalness.
  metalRoughRectArea({ lightColor, rect, reflectedLight, ltc_1, ltc_2 }) {
    const { N, V, P, p0, p1, p2, p3 } = rect;
    const uvLtc = LTC_Uv({ N, V, roughness });
    const t1 = ltc_1.sample(uvLtc).toVar();
    const t2 = ltc_2.sample(uvLtc).toVar();
    const mInv = mat3(vec3(t1.x, 0, t1.y), vec3(0, 1, 0), vec3(t1.z, 0, t1.w)).toVar();
    const f0 = specularColor.mul(metalness.oneMinus());
    const hill = f0.mul(t2.x).add(specularF90.sub(metalness).sub(f0).mul(t2.y));
    const dielectric = this.matc.coat ? hill.mul(this.matcTransmission) : hill;
    reflectedLight.directSpecular.addAssign(lightColor.mul(dielectric).mul(LTC_Evaluate({ N, V, P, mInv, p0, p1, p2, p3 })));
    reflectedLight.directDiffuse.addAssign(lightColor.mul(diffuseContribution)
      .mul(LTC_Evaluate({ N, V, P, mInv: mat3(1, 0, 0, 0, 1, 0, 0, 0, 1), p0, p1, p2, p3 })));
    this.matcRectArea({ lightColor, rect, reflectedLight, ltc_1, baseWeight: metalness });
  }

  // matc's metal under a rect area light, its base lobe weighted by `baseWeight` (the metal-rough
  // mix's metalness; the coat lobe lies over the mix whole).
  matcRectArea({ lightColor, rect, reflectedLight, ltc_1, baseWeight = null }) {
    const baseColour = baseWeight ? lightColor.mul(baseWeight) : lightColor;
    const { N, V, P, p0, p1, p2, p3 } = rect;
    if (this.matc.areaLights !== "engine") {
      const { functions, ltc, rows, url } = this.matc;
      if (!ltc) throw new MatcWebError(`${url}: rect area lights need matc's LTC table; compile with --emit ltc`);
      const texel = texture(ltc, functions.ltcTexcoord({ ndotv: N.dot(V).clamp(), roughness }));
      const lit = step(0, p1.sub(p0).cross(p3.sub(p0)).dot(P.sub(p0)));
      const corners = { N, V, P, q0: p0, q1: p1, q2: p2, q3: p3 };
      const radiance = this.matc.areaLights === "quality"
          ? functions.quadLightFollowing({ ...rows, bbar: this.matcBbar, ltc: texel, roughness, ...corners })
          : this.matcPreintegrated.mul(functions.quadIntegral({ ltc: texel, ...corners }));
      reflectedLight.directSpecular.addAssign(baseColour.mul(radiance).mul(lit));
      if (this.matc.coat) {
        // The coat lobe: matc's LTC at the coat's roughness and normal times its preintegrated F.
        const Ncc = clearcoatNormalView;
        const coatTexel = texture(ltc, functions.ltcTexcoord({ ndotv: Ncc.dot(V).clamp(), roughness: clearcoatRoughness }));
        const integral = functions.quadIntegral({ ltc: coatTexel, ...corners, N: Ncc });
        this.clearcoatSpecularDirect.addAssign(lightColor.mul(this.matcCoatPreintegrated).mul(integral).mul(lit));
      }
      return;
    }
    const t1 = ltc_1.sample(LTC_Uv({ N, V, roughness })).toVar();
    const mInv = mat3(vec3(t1.x, 0, t1.y), vec3(0, 1, 0), vec3(t1.z, 0, t1.w)).toVar();
    reflectedLight.directSpecular.addAssign(
        baseColour.mul(this.matcPreintegrated).mul(LTC_Evaluate({ N, V, P, mInv, p0, p1, p2, p3 })));
    if (this.matc.coat) {
      // The coat lobe: three's LTC shape at the coat's roughness times its preintegrated F.
      const Ncc = clearcoatNormalView;
      const t1Coat = ltc_1.sample(LTC_Uv({ N: Ncc, V, roughness: clearcoatRoughness })).toVar();
      const mInvCoat = mat3(vec3(t1Coat.x, 0, t1Coat.y), vec3(0, 1, 0), vec3(t1Coat.z, 0, t1Coat.w)).toVar();
      this.clearcoatSpecularDirect.addAssign(
          lightColor.mul(this.matcCoatPreintegrated).mul(LTC_Evaluate({ N: Ncc, V, P, mInv: mInvCoat, p0, p1, p2, p3 })));
    }
  }
}

// The coefficients as three rows (red, green, blue: c_0..c_3) of nodes: uniforms for a compiled
// material, per-pixel expressions for a Schlick metal's base colour, for maps through the
// coefficient table and for baked textures.
function coefficientRows(build, source) {
  const kind = sourceKind(build, source);
  if (kind === "material") {
    const [red, green, blue] = source.material.coefficients.map((row) => uniform(new THREE.Vector4(...row)));
    return { red, green, blue };
  }
  if (kind === "schlick") {
    // Schlick's curve of the base colour (colour times map), through the library's
    // matc_coefficients_from_f0 on the curve's rows at F0 = 0.
    const [red, green, blue] = source.schlick.zeroF0Coefficients.map((row) => uniform(new THREE.Vector4(...row)));
    const f0 = diffuseColor.rgb.toConst("matc_f0");
    const { fromF0red, fromF0green, fromF0blue } = build.functions;
    return { red: fromF0red({ red, green, blue, f0 }), green: fromF0green({ red, green, blue, f0 }),
             blue: fromF0blue({ red, green, blue, f0 }) };
  }
  if (kind === "f0Table") {
    // A textured metal under an edge colour or a coat: its coefficients at the base colour
    // (colour times map) from the entries of its F0 table around each channel's F0 (rows 0 to
    // 2); under a coat also the metal seen from the coat (rows 3 to 5), in `underCoat`.
    const table = f0TableTexture(THREE, source.f0Table);
    const f0 = diffuseColor.rgb.toConst("matc_f0");
    const { functions } = build;
    const rowsFrom = (firstRow, key) => {
      const entries = (next) => ["x", "y", "z"].map((c, row) =>
        textureLoad(table, ivec2(functions.f0TableLeft({ f0: f0[c] }).add(next), firstRow + row)));
      const [leftRed, leftGreen, leftBlue] = entries(0);
      const [rightRed, rightGreen, rightBlue] = entries(1);
      const sides = { f0, left_red: leftRed, left_green: leftGreen, left_blue: leftBlue, right_red: rightRed,
                      right_green: rightGreen, right_blue: rightBlue };
      return { red: functions[`${key}red`](sides), green: functions[`${key}green`](sides),
               blue: functions[`${key}blue`](sides) };
    };
    const inAir = rowsFrom(0, "fromF0Entries");
    return source.material.coat ? { ...inAir, underCoat: rowsFrom(3, "fromF0UnderCoat") } : inAir;
  }
  if (kind === "table") {
    const colour = (value) => uniform(new THREE.Color(...rgbOf(value)));
    const r = texture(source.reflectivityMap, uv()).rgb.mul(colour(source.reflectivity)).toConst("matc_r");
    const g = texture(source.edgeTintMap, uv()).rgb.mul(colour(source.edgeTint)).toConst("matc_g");
    const { tableTexcoord, channel } = build.functions;
    const row = (c) => channel({ r: r[c], texel: texture(build.coefficientTable, tableTexcoord({ r: r[c], g: g[c] })).level(0).xy });
    return { red: row("x"), green: row("y"), blue: row("z") };
  }
  // Baked: c_0 = F0 (the F0 map, or the material's base colour), c_1 = 1 - c_0, (c_2, c_3) the maps'.
  const { c2Map, c3Map, f0Map } = source.baked;
  sampleTrilinearly(THREE, [c2Map, c3Map, f0Map]);
  const f0 = (f0Map ? texture(f0Map, uv()).rgb : diffuseColor.rgb).clamp(0, 1).toConst("matc_f0");
  const c2 = texture(c2Map, uv()).rgb.toConst("matc_c2");
  const c3 = texture(c3Map, uv()).rgb.toConst("matc_c3");
  const row = (c) => vec4(f0[c], f0[c].oneMinus(), c2[c], c3[c]);
  return { red: row("x"), green: row("y"), blue: row("z") };
}

// A coated material's coat: its snippet's functions and the under-coat coefficient rows (the
// material's uniforms, or a textured metal's per pixel: `underCoat`; for the base lobe and its
// compensation). The coat's lobe and layering are the compiled material's (weight, index,
// colour, roughness): three's clearcoat, set to 1, only switches its coat light paths on.
function coatOf(compiled, material, areaLights, underCoat = null) {
  if (!material.isMeshPhysicalNodeMaterial) {
    throw new MatcWebError(`${compiled.name} is coated: its coat lobe needs a MeshPhysicalNodeMaterial`);
  }
  checkLayeredAreaLights(compiled, areaLights);
  if (!compiled.coat.functions) throw new MatcWebError("useMatcFresnel (WebGPU) needs this module's loadMaterial");
  material.clearcoat = 1;
  material.clearcoatRoughness = compiled.coat.roughness;
  if (underCoat) return { ...compiled.coat, underCoatRows: underCoat };
  const [red, green, blue] = compiled.coat.underCoatCoefficients.map((row) => uniform(new THREE.Vector4(...row)));
  return { ...compiled.coat, underCoatRows: { red, green, blue } };
}

// Makes `material` (MeshStandardNodeMaterial or MeshPhysicalNodeMaterial) a matc metal with
// `source` = { material } (build.loadMaterial), { schlick }, { material, f0Table },
// { reflectivityMap, edgeTintMap } or { baked }, as
// matc-three.mjs takes them. Returns the material; material.userData.matc.rows holds the
// coefficient nodes (a compiled material's are uniforms: their .value can change without
// recompiling).
// options.areaLights: "matc" (default: matc's LTC table and horizon-clipped integral, checked
// against the CPU runtime), "quality" (the same with matc's quality level: the lobe's shape and
// the Fresnel follow the light across the lobe, docs/ltc.md; a quarter more per light) or "engine"
// (three's LTC shape with matc's Fresnel: cheaper; docs/web-engines.md measures them).
// options.metalRough: glTF's metal-rough model per pixel (docs/gltf.md): the material keeps its
// metalness (and metalnessNode, a glTF metal's map), and matc's metal replaces three's metal lobe
// only, mixed with three's own dielectric by the pixel's metalness in every light path (under a
// matc coat, the dielectric seen through it as glTF layers a clear coat).
// options.bareFilm: `source` is the bare metal that matc compiled from the material's film (index 1,
// 0 nm or no coverage: docs/thin-film.md); it takes the place of three's iridescence, which is
// switched off, as a filmed metal does (the glTF loaders set it).
export function useMatcFresnel(material, build, source, { areaLights = "matc", metalRough = false, bareFilm = false } = {}) {
  checkAreaLights(areaLights);
  if (!material?.isMeshStandardNodeMaterial) {
    throw new MatcWebError("useMatcFresnel (WebGPU) takes a MeshStandardNodeMaterial or MeshPhysicalNodeMaterial");
  }
  if (!build?.functions) throw new MatcWebError("useMatcFresnel (WebGPU) needs this module's loadMatcBuild");
  // three's lighting model computes an iridescent material's Fresnel itself (the film over the
  // metal with its extinction taken as 0), in place of the one matc replaces.
  // A filmed matc metal takes its place (matc's film over the metal's own index).
  const film = source?.material?.film ?? null;
  const replacesIridescence = checkIridescence(material.iridescence > 0, film, bareFilm);
  checkLightingModel();
  const { underCoat, ...rows } = coefficientRows(build, source);
  if (film) checkLayeredAreaLights(source.material, areaLights);
  if (replacesIridescence) material.iridescence = 0;
  const coat = source?.material?.coat ? coatOf(source.material, material, areaLights, underCoat) : null;
  const matc = { rows, functions: build.functionsByBasis?.[sourceBasis(build, source)] ?? build.functions, lut: build.lut, ltc: build.ltc, url: build.url, areaLights, coat,
                 film: film && filmTexture(THREE, film.table), source, metalRough };
  if (!metalRough) {
    material.metalness = 1;
    material.metalnessNode = null;
  }
  material.setupLightingModel = () => new MatcPhysicalLightingModel(matc, material);
  material.userData.matc = matc;
  // The coefficients are this material's uniforms: no pipeline shared with another material.
  material.customProgramCacheKey = () => `matc:${material.uuid}:${areaLights}:${metalRough}`;
  material.needsUpdate = true;
  return material;
}
