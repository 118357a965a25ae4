// What the engine integration tests share (check-three-engine.mjs, check-babylon-engine.mjs): the
// probe scene (a plane z = 0 seen from z = 1 with a 90 degree field of view into a 64 x 64 float
// target), the builds they load (good ones and the ones that must fail), the CPU runtime's value
// at each probe pixel for each light (`matc eval`), and the comparison.
import { cpSync, mkdirSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { kWebRoots, runPage } from "./browser-page.mjs";
import { rectLightGeometry } from "./engine-scene.mjs";
import { check, finish } from "./report.mjs";
import { compensatedFbar, kPreintegratedTolerance, run } from "./shader-cases.mjs";

export const kProbeSize = 64;
// [39, 37] sees the point light near its mirror direction: the sharp coat lobe of the coated metal
// (its peak, at [37, 35], is too steep for float32 positions to meet 1e-4).
export const kProbePixels = [[32, 32], [5, 60], [60, 10], [1, 1], [40, 20], [62, 40], [39, 37]];
export const kProbeRoughness = [0.3, 0.7];
export const kProbeMaterials = ["figure2_edge_tint", "beryllium"];
// A coated metal (measured copper under a tinted lacquer of roughness 0.1): both lobes.
export const kProbeCoated = "copper_lacquered";
// A filmed metal (measured titanium under a 45 nm anodic film, docs/thin-film.md): F and Fbar from
// its own table.
export const kProbeFilmed = "titanium_anodised_blue";
// The same film under a clear lacquer (docs/thin-film.md, "Under a coat"): its table is the base
// lobe, the coat lobe its snippet's.
export const kProbeFilmCoated = "titanium_anodised_lacquered";
export const kPointLight = { position: [0.3, 0.2, 0.8], intensity: 0.7 };
// A rect area light above the probe plane: centre, size and radiance (each engine places its
// corners: three.js's looks at the origin, Babylon's faces -z).
export const kProbeRectLight = { position: [-0.4, 0.3, 0.9], width: 0.8, height: 0.5, intensity: 4.0 };
// How three.js (WebGL and WebGPU) renders the probes: its GGX alpha (roughness clamped at 0.045,
// squared) and its rect light, which looks at the origin.
export const kThreeJsProbeTerms = {
  alphaOf: (r) => Math.max(r, 0.045) ** 2,
  rect: { light: kProbeRectLight, corners: rectLightGeometry(kProbeRectLight).corners },
};
// Babylon.js's: its GGX alpha (roughness squared plus its minimum variance), its coat lobe's
// visibility (Kelemen's, computeClearCoatLighting), and its RectAreaLight (a centre, its width
// along world x and height along world y, lighting the side towards -z, Babylon's winding), whose
// specular its energy conservation scales too.
const babylonRectCorners = ({ position: [x, y, z], width, height }) => {
  const w = width / 2, h = height / 2;
  return [[x + w, y - h, z], [x - w, y - h, z], [x - w, y + h, z], [x + w, y + h, z]];
};
export const kBabylonProbeTerms = {
  alphaOf: (r) => r * r + 0.0005,
  coatVisibility: "kelemen",
  rect: { light: kProbeRectLight, corners: babylonRectCorners(kProbeRectLight), compensated: true },
};
export const kTextured = { reflectivity: [0.9, 0.6, 0.3], edgeTint: [0.8, 0.5, 0.2] };
export const kBaked = { reflectivity: [0.95, 0.64, 0.54], edgeTint: [1.0, 0.75, 0.4] };
// A Schlick metal whose F0 is the engine material's base colour (the source { schlick }: a textured
// glTF metal's, here a plain colour).
export const kSchlick = { f0: [0.9, 0.55, 0.3] };
const kSchlickMaterial = (f0) => ({ name: "schlick_probe", color_space: "lin_rec709",
                                    f82_tint: { f0, tint: [1, 1, 1] } });
// An edge-coloured metal whose F0 is the engine material's base colour (the source
// { material, f0Table }: a textured glTF metal under an edge colour). Its F0 table is the metal
// compiled at 33 values of F0, entry i at (i / 32)^4, as `matc gltf` writes it; the colour's
// channels sit on entries 30, 16 and 28 (exact in binary), where the table holds the metal
// compiled at that F0: what the CPU runtime predicts. (The interpolation between entries is
// checked against the CPU runtime on lavapipe.)
export const kF0Table = { f0: [0.7724761962890625, 0.0625, 0.586181640625], tint: [0.9, 0.75, 0.6] };
const kF0TableMaterial = (name, f0) => ({ name, color_space: "lin_rec709", f82_tint: { f0, tint: kF0Table.tint } });
// The same metal under a partial clear coat (the source { material, f0Table } of a textured glTF
// metal under a coat): its table holds each entry's coefficients in air and under the coat, and
// the partial coat lets the metal in air show through, so both halves count. The build compiles it
// at a factor that is not the colour, as a glTF asset's factor and texture differ: a page that
// took the material's own rows instead of the table's would draw the factor's metal.
const kF0TableCoated = { name: "f0_table_coated_probe", coat: { weight: 0.7, ior: 1.5, roughness: 0.1 },
                                factor: [0.3, 0.3, 0.3] };
const kF0TableCoatedMaterial = (name, f0) => ({ ...kF0TableMaterial(name, f0), coat: kF0TableCoated.coat });

// ["--basis", "powers"] for a one-basis build (runProbeCheck's --one-basis), else nothing: what
// every compile and evaluation of the probe materials adds (the builds that must be refused keep
// their own options).
let gBasisOptions = [];

// Vector helpers (double precision; the GPU's float32 stays well within the tolerance).
export const sub = (a, b) => a.map((x, i) => x - b[i]);
export const add = (a, b) => a.map((x, i) => x + b[i]);
export const scale = (a, s) => a.map((x) => x * s);
export const dot = (a, b) => a.reduce((s, x, i) => s + x * b[i], 0);
export const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
export const normalize = (a) => scale(a, 1 / Math.sqrt(dot(a, a)));

// Pixel (x, y), y up, sees P = (u, v, 0), u, v = 2 (x + 0.5) / 64 - 1; the normal is +z.
const kNormal = [0, 0, 1];
const pointAt = ([x, y]) => [(2 * (x + 0.5)) / kProbeSize - 1, (2 * (y + 0.5)) / kProbeSize - 1, 0];
const viewAt = (pixel) => normalize(sub([0, 0, 1], pointAt(pixel)));
// A probe pixel's NdotV on the plane (the engines' shading normal +z).
export const probeNdotV = (pixel) => dot(kNormal, viewAt(pixel));

// GGX without F, D x height-correlated Smith visibility (or Kelemen's 1 / (4 (v.h)^2) with
// visibility "kelemen"), for the engine's alpha.
function ggxWithoutFresnel(l, v, alpha, visibilityTerm = "smith") {
  const a2 = alpha * alpha;
  const h = normalize(add(l, v));
  const nl = Math.max(dot(kNormal, l), 0), nv = Math.max(dot(kNormal, v), 0);
  const nh = Math.max(dot(kNormal, h), 0);
  const gv = nl * Math.sqrt(a2 + (1 - a2) * nv * nv);
  const gl = nv * Math.sqrt(a2 + (1 - a2) * nl * nl);
  const visibility = visibilityTerm === "kelemen" ? 0.25 / Math.max(dot(v, h) ** 2, 1e-6)
                                                  : 0.5 / Math.max(gv + gl, 1e-6);
  const d = a2 / (Math.PI * (nh * nh * (a2 - 1) + 1) ** 2);
  return { value: d * visibility, vdoth: Math.max(dot(v, h), 0) };
}

// A corner in the CPU runtime's shading frame: normal +z, the view in the xz-plane towards +x.
function toShadingFrame(corner, pixel) {
  const p = pointAt(pixel), v = viewAt(pixel);
  const t1 = normalize(sub(v, scale(kNormal, dot(v, kNormal))));
  const t2 = cross(kNormal, t1);
  const d = sub(corner, p);
  return [dot(d, t1), dot(d, t2), dot(d, kNormal)];
}

const list = (values) => values.join(",");

// `matc eval` of a material (`args`: its file, or --reflectivity/--edge-tint) at every probe:
// Fbar at (NdotV, roughness) and F at the point light's v.h (`terms`).
function evaluateAtProbes(matc, args, ndotv, roughness, terms) {
  return JSON.parse(run(matc, [
    "eval", ...args, ...gBasisOptions, "--lut-precision", "f32", "--no-reference", "--ndotv", list(ndotv),
    "--roughness", list(ndotv.map(() => roughness)), "--mu", list(terms.map((t) => t.vdoth))]));
}

// `matc eval --quad-light` of a material at every probe for the rect light (its corners in each
// probe's shading frame): the LTC radiance alone (--no-reference: a coated material's layered
// references were most of an engine check's time).
function quadLightsAtProbes(matc, args, ndotv, roughness, rect) {
  return kProbePixels.map((pixel, i) => {
    const quad = rect.corners.map((corner) => toShadingFrame(corner, pixel).join(",")).join(";");
    return JSON.parse(run(matc, [
      "eval", ...args, ...gBasisOptions, "--lut-precision", "f32", "--ndotv", String(ndotv[i]),
      "--roughness", String(roughness), "--quad-light", quad, "--no-reference"]));
  });
}

// Compiles what the pages load into dir: out/ (the probe materials, every table in f32), baked/
// (`matc bake` of kBaked, f32), and the builds that must be refused: json-only/ (no shader
// library, no table), mixed-table/ (the extended basis' table beside powers coefficients) and
// out/beryllium_extended.json (extended-basis coefficients beside powers tables), and
// out/copper_lacquered_without_snippet.json (a coated material without its shader snippet).
export function prepareProbeBuilds(matc, materialsDir, dir) {
  const out = join(dir, "out");
  const materialFiles = [...kProbeMaterials, kProbeCoated, kProbeFilmed, kProbeFilmCoated]
                          .map((name) => join(materialsDir, `${name}.json`));
  run(matc, ["-q", "-o", out, "--emit", "glsl,wgsl,json,lut,ltc,coefficient-table", ...gBasisOptions,
             "--lut-precision", "f32", "--coefficient-table-precision", "f32", ...materialFiles,
             f0TableCoatedFile(join(dir, "f0_table_coated_factor"), kF0TableCoated.factor)]);
  run(matc, ["bake", "-q", "--reflectivity", kBaked.reflectivity.join(","), "--edge-tint",
             kBaked.edgeTint.join(","), "--name", "probe", "--precision", "f32", "--f0", "-o",
             join(dir, "baked")]);
  run(matc, ["-q", "-o", join(dir, "json-only"), "--emit", "json", materialFiles[1]]);
  const extended = join(dir, "extended");
  run(matc, ["-q", "-o", extended, "--basis", "extended", "--emit", "glsl,json,lut",
             "--lut-precision", "f32", materialFiles[1]]);
  cpSync(out, join(dir, "mixed-table"), { recursive: true });
  for (const file of ["matc_lut.ktx2", "matc_lut.ktx2.json"]) {
    cpSync(join(extended, file), join(dir, "mixed-table", file));
  }
  cpSync(join(extended, "beryllium.json"), join(out, "beryllium_extended.json"));
  // A coated material whose snippet the build lacks.
  cpSync(join(out, `${kProbeCoated}.json`), join(out, `${kProbeCoated}_without_snippet.json`));
  return { out, roots: { out, baked: join(dir, "baked"), "json-only": join(dir, "json-only"),
                         "mixed-table": join(dir, "mixed-table") } };
}

// The renders a page makes: every material at every roughness under each light, and under the rect
// light at the quality level (render.areaLights, useMatcFresnel's option); the filmed metal at
// every roughness under each light (matc's LTC: the quality level takes bare metals); the textured
// and baked metals under the environment and the point light.
export function probeRenders() {
  const renders = [];
  for (const source of kProbeMaterials) {
    for (const roughness of kProbeRoughness) {
      for (const light of ["environment", "point", "rect"]) {
        renders.push({ key: `${source} ${light} r=${roughness}`, source, light, roughness, areaLights: "matc" });
      }
      // The rect light at the quality level (areaLights "quality").
      renders.push({ key: `${source} rect quality r=${roughness}`, source, light: "rect", roughness,
                     areaLights: "quality" });
    }
  }
  for (const roughness of kProbeRoughness) {
    for (const light of ["environment", "point", "rect"]) {
      renders.push({ key: `${kProbeFilmed} ${light} r=${roughness}`, source: kProbeFilmed, light, roughness, areaLights: "matc" });
    }
  }
  for (const source of [...kColourSources, kF0TableCoated.name]) {
    for (const light of ["environment", "point"]) {
      renders.push({ key: `${source} ${light} r=0.3`, source, light, roughness: 0.3 });
    }
  }
  for (const source of [kProbeCoated, kProbeFilmCoated]) {
    for (const light of ["environment", "point", "rect"]) {
      renders.push({ key: `${source} ${light} r=0.3`, source, light, roughness: 0.3, areaLights: "matc" });
    }
  }
  return renders;
}

// The CPU runtime's value at every probe of the given renders: compensated Fbar under the white
// environment, irradiance x GGX x F(v.h) x compensation under the point light (alphaOf gives the
// engine's GGX alpha for a roughness), the rect light's radiance (rect.light.intensity) x `L_ltc`
// (rect.corners in world space; `L_ltc_following` at the quality level), times the compensation
// too where the engine applies it to area lights (rect.compensated). bare and coated name the
// materials (<name>.json in materialsDir and, compiled, in out): the probe checks' by default;
// coatedFiles[name] = { file, compiledIn } a coated one's material file and compiled folder instead.
// coatLobeOnly: a coated metal's coat lobe alone (what lies over whatever is under the coat).
export function expectedProbes({ matc, materialsDir, out, alphaOf, coatVisibility, rect, renders,
                                 bare = [...kProbeMaterials, kProbeFilmed], coated = [kProbeCoated, kProbeFilmCoated],
                                 coatedFiles = {},
                                 coatLobeOnly = false }) {
  const wanted = new Set(renders.map((render) => render.key));
  const ndotv = kProbePixels.map((pixel) => Math.fround(dot(kNormal, viewAt(pixel))));
  const pointTerms = kProbeRoughness.map((roughness) => kProbePixels.map((pixel) => {
    const toLight = sub(kPointLight.position, pointAt(pixel));
    const distance2 = dot(toLight, toLight);
    const l = normalize(toLight);
    const brdf = ggxWithoutFresnel(l, viewAt(pixel), alphaOf(roughness));
    return { irradiance: (kPointLight.intensity / Math.max(distance2, 0.01)) * Math.max(l[2], 0),
             ggx: brdf.value, vdoth: brdf.vdoth, light: l, view: viewAt(pixel) };
  }));
  const albedo = (roughness) => JSON.parse(run(matc, [
    "eval", "--reflectivity", "1", "--edge-tint", "1", "--lut-precision", "f32", "--no-reference",
    "--ndotv", list(ndotv), "--roughness", list(ndotv.map(() => roughness))])).Fbar_table.map((e) => e[0]);
  const expected = {};
  for (const [source, args, f0Of, fbarKey, fKey] of [
    ...bare.map((name) => [name, [join(materialsDir, `${name}.json`)], null, "Fbar", "F"]),
    ["textured", ["--reflectivity", list(kTextured.reflectivity), "--edge-tint", list(kTextured.edgeTint),
                  "--coefficient-table-precision", "f32"], kTextured.reflectivity, "Fbar_table", "F_table"],
    ["baked", ["--reflectivity", list(kBaked.reflectivity), "--edge-tint", list(kBaked.edgeTint)],
     kBaked.reflectivity, "Fbar_compiled", "F_compiled"],
    ["schlick", [schlickFile(out)], kSchlick.f0, "Fbar", "F"],
    ["f0table", [f0TableFile(out)], kF0Table.f0, "Fbar", "F"],
  ]) {
    for (const roughness of kColourSources.includes(source) ? [0.3] : kProbeRoughness) {
      const key = (light) => `${source} ${light} r=${roughness}`;
      if (!["environment", "point", "rect", "rect quality"].some((light) => wanted.has(key(light)))) continue;
      const terms = pointTerms[kProbeRoughness.indexOf(roughness)];
      const evaluated = evaluateAtProbes(matc, args, ndotv, roughness, terms);
      const f0 = f0Of ?? JSON.parse(readFileSync(join(out, `${source}.json`), "utf8"))
                            .coefficients.map((row) => row[0]);
      const e = albedo(roughness);
      if (wanted.has(key("environment"))) {
        expected[key("environment")] = evaluated[fbarKey].map((fbar, i) => compensatedFbar(fbar, f0, e[i]));
      }
      if (wanted.has(key("point"))) {
        expected[key("point")] = terms.map((t, i) => {
          const compensated = compensatedFbar(evaluated[fKey][i], f0, e[i]);  // F (1 + F0 (1 - E) / E)
          return compensated.map((value) => t.irradiance * t.ggx * value);
        });
      }
      if (wanted.has(key("rect")) || wanted.has(key("rect quality"))) {
        const lights = quadLightsAtProbes(matc, args, ndotv, roughness, rect);
        // L_ltc (areaLights "matc") or L_ltc_following (the quality level).
        const radiance = (field) => lights.map((light, i) => {
          const rgb = light[field][0].map((value) => value * rect.light.intensity);
          return rect.compensated ? compensatedFbar(rgb, f0, e[i]) : rgb;
        });
        if (wanted.has(key("rect"))) expected[key("rect")] = radiance("L_ltc");
        if (wanted.has(key("rect quality"))) expected[key("rect quality")] = radiance("L_ltc_following");
      }
    }
  }
  for (const name of coated) {
    const { file, compiledIn } = coatedFiles[name] ?? { file: join(materialsDir, `${name}.json`), compiledIn: out };
    Object.assign(expected, expectedCoatedProbes({ name, file, out: compiledIn, matc, alphaOf, coatVisibility, rect,
                                                   wanted, ndotv, albedo, pointTerms, coatLobeOnly }));
  }
  return expected;
}

// A coated metal's probes at roughness 0.3, both lobes as the CPU runtime evaluates them: the
// base lobe (the metal through the coat) with the multiple scattering of a bare metal whose F0 is
// the metal's under the coat, the coat lobe (its weight included) at the coat's roughness, without.
// Rect lights: `L_ltc_base` and `L_ltc_coat` of `matc eval --quad-light`, the base's compensated
// where the engine compensates rect lights. engine.coatVisibility: the coat lobe's visibility term
// where the engine's is not the base's (Babylon's Kelemen).
function expectedCoatedProbes({ name, file, matc, out, alphaOf, coatVisibility, rect, wanted, ndotv, albedo,
                                pointTerms, coatLobeOnly }) {
  const baseWeight = coatLobeOnly ? 0 : 1;
  const roughness = 0.3;
  const key = (light) => `${name} ${light} r=${roughness}`;
  const expected = {};
  if (!["environment", "point", "rect"].some((light) => wanted.has(key(light)))) return expected;
  const compiled = JSON.parse(readFileSync(join(out, `${name}.json`), "utf8"));
  const underCoatF0 = compiled.coat.under_coat_coefficients.map((row) => row[0]);
  const coatAlpha = alphaOf(compiled.coat.input.roughness);
  const terms = pointTerms[kProbeRoughness.indexOf(roughness)];
  const evaluated = evaluateAtProbes(matc, [file], ndotv, roughness, terms);
  const e = albedo(roughness);
  const layered = (base, coat, i) => compensatedFbar(base, underCoatF0, e[i]).map((value) => baseWeight * value + coat);
  if (wanted.has(key("environment"))) {
    expected[key("environment")] = ndotv.map((_, i) => layered(evaluated.Fbar_base[i], evaluated.Fbar_coat[i], i));
  }
  if (wanted.has(key("point"))) {
    expected[key("point")] = terms.map((t, i) => {
      const coatGgx = ggxWithoutFresnel(t.light, t.view, coatAlpha, coatVisibility).value;
      const base = compensatedFbar(evaluated.F_base[i], underCoatF0, e[i]).map((value) => value * t.ggx);
      return base.map((value) => t.irradiance * (baseWeight * value + coatGgx * evaluated.F_coat[i]));
    });
  }
  if (wanted.has(key("rect"))) {
    expected[key("rect")] = quadLightsAtProbes(matc, [file], ndotv, roughness, rect).map((light, i) => {
      const base = light.L_ltc_base[0].map((value) => value * rect.light.intensity);
      const coat = light.L_ltc_coat[0] * rect.light.intensity;
      return (rect.compensated ? compensatedFbar(base, underCoatF0, e[i]) : base).map((value) => baseWeight * value + coat);
    });
  }
  return expected;
}

// Every rendered probe against the CPU runtime, to 1e-4 (relative above 1); returns the largest
// difference.
export function compareProbes(renders, expected) {
  let worst = 0;
  for (const [key, pixels] of Object.entries(expected)) {
    const rendered = renders[key];
    check(Array.isArray(rendered), `${key}: not rendered`);
    if (!Array.isArray(rendered)) continue;
    pixels.forEach((rgb, i) => rgb.forEach((value, c) => {
      const difference = Math.abs(rendered[i][c] - value) / Math.max(1, Math.abs(value));
      worst = Math.max(worst, difference);
      check(difference <= kPreintegratedTolerance,
            `${key}, pixel ${kProbePixels[i]}, channel ${c}: rendered ${rendered[i][c]}, CPU runtime ${value}`);
    }));
    // Every light must reach the probes (a light that lit nothing would pass trivially).
    const lit = pixels.filter((rgb) => rgb.some((value) => value > 1e-3)).length;
    check(lit >= 3, `${key}: only ${lit} of ${kProbePixels.length} probes lit (${JSON.stringify(pixels)})`);
  }
  return worst;
}

// The inputs a page must refuse, each with a phrase its message must hold; pages run each as
// failure(key, action) and report { thrown, message, logged }.
export const kFailures = {
  missing_directory: "is this a matc output directory",
  no_glsl_no_lut: "output (the shader library); compile with --emit",
  table_of_another_basis: "a table of basis extended",
  coefficients_of_another_basis: "do not belong together",
  unknown_material: 'is "unobtainium" one of this build\'s materials',
  engine_changed: "changed (0 matches for the text the patch",
  textured_without_edge_tint: "needs both reflectivityMap and edgeTintMap",
  schlick_not_zero_f0: "zeroF0Coefficients must be rows [0, 1, c_2, c_3] of finite numbers",
  f0_table_without_material: "an F0 table (f0Table) comes with its { material }",
  coated_f0_table_without_under_coat: "f0Table: a coated metal's table needs underCoatCoefficients",
  unknown_area_light_option: 'areaLights: "fast"; allowed: "matc", "quality", "engine"',
  area_light_option_escaped: 'areaLights: "x\\nmatc: forged"; allowed',
  bare_film_not_boolean: "bareFilm must be true or false, not a string",
  coated_quality_area_lights: "is coated: the quality-level area lights take bare metals",
  filmed_quality_area_lights: "is filmed: the quality-level area lights take bare metals",
  filmed_f0_table: "is filmed: its own table holds the film over one metal",
  coated_without_snippet: "a coated material needs its own shader snippet",
};

export function checkFailures(failures) {
  for (const [key, phrase] of Object.entries(kFailures)) {
    const failure = failures[key];
    check(failure?.thrown === true, `${key}: did not throw`);
    if (!failure?.thrown) continue;
    check(failure.message.includes(phrase), `${key}: "${failure.message}" does not say "${phrase}"`);
    check(failure.logged === true, `${key}: nothing written to the console`);
  }
  return Object.keys(kFailures).length;
}

// The sources rendered at roughness 0.3 under the environment and the point light only.
const kColourSources = ["textured", "baked", "schlick", "f0table"];

// The F0-table probe metal's material file at its colour (in `dir`), for the CPU runtime's side.
function f0TableFile(dir) {
  const file = join(dir, "f0_table_probe.json");
  writeFileSync(file, JSON.stringify(kF0TableMaterial("f0_table_probe", kF0Table.f0)));
  return file;
}

// An F0-table probe metal's table: the metal (material(name, f0)) compiled by matc at
// F0 = (i / 32)^4 on every channel, as MATC_materials_fresnel's f0Table holds it (33 entries of
// rows R, G, B; a coated metal's also under the coat).
function f0TableOf(matc, dir, material) {
  mkdirSync(dir);
  const files = Array.from({ length: 33 }, (_, i) => {
    const file = join(dir, `entry_${i}.json`);
    writeFileSync(file, JSON.stringify(material(`entry_${i}`, Array(3).fill((i / 32) ** 4))));
    return file;
  });
  run(matc, ["-q", "-o", join(dir, "out"), "--emit", "json", ...gBasisOptions, ...files]);
  const compiled = files.map((_, i) => JSON.parse(readFileSync(join(dir, "out", `entry_${i}.json`), "utf8")));
  return { basis: compiled[0].basis.name, coefficients: compiled.map((entry) => entry.coefficients),
           ...(compiled[0].coat ? { underCoatCoefficients: compiled.map((entry) => entry.coat.under_coat_coefficients) } : {}) };
}

// The coated F0-table probe metal's material file at `f0` (in `dir`, made if missing): at its
// factor for the probe build (its coat and snippet), at its colour for the CPU runtime's side.
function f0TableCoatedFile(dir, f0) {
  mkdirSync(dir, { recursive: true });
  const file = join(dir, `${kF0TableCoated.name}.json`);
  writeFileSync(file, JSON.stringify(kF0TableCoatedMaterial(kF0TableCoated.name, f0)));
  return file;
}

// The same metal at its colour, compiled: what the CPU runtime's side evaluates.
function f0TableCoatedAtColour(matc, dir) {
  const file = f0TableCoatedFile(join(dir, "f0_table_coated_colour"), kF0Table.f0);
  const compiledIn = join(dir, "f0_table_coated_colour", "out");
  run(matc, ["-q", "-o", compiledIn, "--emit", "json", ...gBasisOptions, file]);
  return { file, compiledIn };
}

// The Schlick probe metal's material file (in `dir`), for the CPU runtime's side.
function schlickFile(dir) {
  const file = join(dir, "schlick_probe.json");
  writeFileSync(file, JSON.stringify(kSchlickMaterial(kSchlick.f0)));
  return file;
}

// The coefficients at F0 = 0 of Schlick's curve, compiled by matc (the build's basis for it: the
// default, or f82 in a per-material build), and that basis, for the { schlick } source.
function zeroF0Coefficients(matc, dir) {
  const file = join(dir, "zero_f0.json");
  writeFileSync(file, JSON.stringify({ ...kSchlickMaterial([0, 0, 0]), name: "zero_f0" }));
  run(matc, ["-q", "-o", join(dir, "zero_f0"), "--emit", "json", ...gBasisOptions, file]);
  const compiled = JSON.parse(readFileSync(join(dir, "zero_f0", "zero_f0.json"), "utf8"));
  return { basis: compiled.basis.name, zeroF0Coefficients: compiled.coefficients };
}

// The whole check for one engine: builds, the page (engine.page(config) -> HTML, which renders
// config.renders into out.renders and runs page-bad-inputs.mjs), the CPU side, the comparison.
// engine: { name, page, alphaOf (its GGX alpha for a roughness), rect: { light (for the page),
// corners (world space), compensated } (where it renders rect lights) }; optionally runPage
// options (realTime, browserArgs).
// With --compile-in-page after them, webDir is the staged npm package (build/npm) and the page
// compiles the probe materials itself (tests/js/page-probe-build.mjs); the renders are those of
// compiled materials (the textured and baked sources are the build directory's). By default every
// probe material is compiled and evaluated as a default build does, a basis per material: the
// measured metals on the table's first layer, the F82-tint ones (the Schlick and F0-table metals)
// through the f82 basis' functions and layer. With --one-basis, in a one-basis build (matc --basis
// powers): every metal on one layer and the first basis' functions.
export async function runProbeCheck(engine, [matc, materialsDir, webDir, mode]) {
  gBasisOptions = mode === "--one-basis" ? ["--basis", "powers"] : [];
  const dir = mkdtempSync(join(tmpdir(), "matc-engine-probes-"));
  try {
    const { out, roots } = prepareProbeBuilds(matc, materialsDir, dir);
    const materials = [...kProbeMaterials, kProbeCoated, kProbeFilmed, kProbeFilmCoated];
    const compileInPage = mode === "--compile-in-page";
    const renders = probeRenders().filter((render) => !compileInPage || materials.includes(render.source));
    const materialTexts = Object.fromEntries(
      materials.map((name) => [name, readFileSync(join(materialsDir, `${name}.json`), "utf8")]));
    const config = { materials, coated: kProbeCoated, filmed: kProbeFilmed, pixels: kProbePixels, renders, point: kPointLight,
                     rect: engine.rect?.light, textured: kTextured, compileInPage, materialTexts,
                     schlick: { color: kSchlick.f0, ...zeroF0Coefficients(matc, dir) },
                     f0Table: { color: kF0Table.f0, ...f0TableOf(matc, join(dir, "f0_table_entries"), kF0TableMaterial) },
                     f0TableCoated: { name: kF0TableCoated.name,
                                      ...f0TableOf(matc, join(dir, "f0_table_coated_entries"), kF0TableCoatedMaterial) } };
    const result = await runPage({ html: engine.page(config), roots: { ...kWebRoots, web: webDir, ...roots }, dir,
                                   ...(engine.runPage ?? {}) });
    check(result.errors.length === 0, `${engine.name}: ${result.errors.join("\n")}`);
    const expected = expectedProbes({ matc, materialsDir, out, alphaOf: engine.alphaOf,
                                      coatVisibility: engine.coatVisibility, rect: engine.rect, renders,
                                      coated: [kProbeCoated, kProbeFilmCoated, kF0TableCoated.name],
                                      coatedFiles: { [kF0TableCoated.name]: f0TableCoatedAtColour(matc, dir) } });
    const worst = compareProbes(result.renders ?? {}, expected);
    const refused = checkFailures(result.failures ?? {});
    console.log(`${engine.label} with matc's Fresnel${compileInPage ? " (materials compiled in the page)" : ""}` +
                `${gBasisOptions.length ? " (a one-basis build, --basis powers)" : ""}: ` +
                `${renders.length} renders x ` +
                `${kProbePixels.length} probes, largest difference from the CPU runtime ` +
                `${worst.toExponential(2)}; ${refused} bad inputs checked`);
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
  finish();
}
