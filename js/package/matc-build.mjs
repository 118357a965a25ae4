// What the web engine integrations share (three/matc-three.mjs, babylon/matc-babylon.mjs): reading
// a matc build directory in a browser (manifest, shader library, tables, compiled materials,
// each checked against the others), or making the same from materials compiled in the page by
// the package's WebAssembly compiler, and patching an engine's shader text at anchors that must
// be found exactly once. Engine-neutral: tables come back as typed arrays for the engine's own
// texture class. KTX2 containers are read with ktx-parse (npm, the reader three.js bundles),
// imported when a KTX2 table is read: raw tables (the package's) need nothing else.
import { coatedSnippet } from "./coated-snippet.mjs";
import { tableFiles } from "./tables.mjs";

async function ktx2Reader() {
  try {
    return (await import("ktx-parse")).read;
  } catch (error) {
    throw new MatcWebError(`KTX2 tables need the ktx-parse package (${error.message}); install it, or ` +
                           "compile with --lut raw");
  }
}

// The matc version whose outputs this code reads (matc_version in the manifest).
export const kMatcVersion = "0.1.0";

// A problem that must stop the material from being used: reported on the console and thrown.
export class MatcWebError extends Error {
  constructor(message) {
    super(`matc: ${message}`);
    this.name = "MatcWebError";
    console.error(this.message);
  }
}

// ---- Patching an engine's shader text. ----

// A pattern for `anchor` that ignores how whitespace is laid out (engines' builds collapse blank
// lines and indentation) but nothing else.
export function anchorPattern(anchor) {
  const words = anchor.trim().split(/\s+/).map((word) => word.replace(/[.*+?^${}()|[\]\\]/g, "\\$&"));
  return new RegExp(words.join("\\s*"), "g");
}

// How many times `anchor` occurs in `source`.
export function countAnchor(source, anchor) {
  return (source.match(anchorPattern(anchor)) ?? []).length;
}

// Checks each patch's anchor against the engine's shader sources (name -> text): found exactly
// `patch.count ?? 1` times, or the engine changed and the material must not be used.
export function checkAnchors(engine, sources, patches, tested) {
  for (const patch of patches) {
    const source = sources[patch.source];
    if (typeof source !== "string") {
      throw new MatcWebError(`${engine} has no shader source ${patch.source}; the integration was tested with ${tested}`);
    }
    const count = countAnchor(source, patch.anchor);
    if (count !== (patch.count ?? 1)) {
      throw new MatcWebError(
          `${engine}: the shader source ${patch.source} changed (${count} matches for the text the patch ` +
          `"${patch.what}" replaces, expected ${patch.count ?? 1}); the integration was tested with ` +
          `${tested}: pin that version or update the patch`);
    }
  }
}

// ---- The GLSL both integrations put into their engine's physical shader. ----

// Declarations of the tables and the globals the patched light paths read; `uniforms` adds the
// coefficient sources' vector uniforms (engines that bind them through a uniform block declare
// those themselves).
export function declarationsGlsl(library, { uniforms }) {
  const vectors = uniforms ? "\tuniform vec4 matc_red;\n\tuniform vec4 matc_green;\n\tuniform vec4 matc_blue;\n" : "";
  const colours = uniforms ? "\tuniform vec3 matc_reflectivity;\n\tuniform vec3 matc_edge_tint;\n" : "";
  return `
${library}
uniform sampler2D matc_lut;
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
`;
}

// What the patched light paths call for the base lobe, and for a coated material's coat lobe
// (docs/coating.md): the library's functions on this pixel's coefficients, or, for a material
// loaded with a coat (build.loadMaterial), its own snippet's (<name>.glsl: the metal seen through
// the coat, attenuated and tinted by it, and the coat's dielectric Fresnel with its weight).
// matc_coat_bbar is matc_lut's texel at the coat's roughness and matc_ndotv the pixel's NdotV,
// set before the lights with the rest.
export function lobesGlsl(material) {
  if (!material?.coat) {
    return `
vec3 matc_base_fresnel(float mu) { return matc_fresnel(matc_c, mu); }
vec3 matc_base_preintegrated() { return matc_fresnel_preintegrated(matc_c, matc_bbar); }
vec3 matc_base_compensation() { return matc_energy_compensation(matc_c, matc_bbar); }
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
	matc_bbar = texture(matc_lut, matc_lut_texcoord(${ndotv}, ${roughness}));
#ifdef MATC_COATED
	matc_ndotv = ${ndotv};
	matc_coat_bbar = texture(matc_lut, matc_lut_texcoord(matc_ndotv, ${coatRoughness}));
#endif
`;
}

// ---- A matc build directory. ----

async function fetchChecked(url, hint) {
  let response;
  try {
    response = await fetch(url);
  } catch (error) {
    throw new MatcWebError(`${url}: cannot be read (${error.message}); ${hint}`);
  }
  if (!response.ok) throw new MatcWebError(`${url}: ${response.status} ${response.statusText}; ${hint}`);
  return response;
}

async function fetchJson(url, hint) {
  const text = await (await fetchChecked(url, hint)).text();
  try {
    return JSON.parse(text);
  } catch (error) {
    throw new MatcWebError(`${url}: not JSON (${error.message}); ${hint}`);
  }
}

// Vulkan formats of the tables matc writes: channels and whether texels are half floats.
const kVkFormats = {
  83: { channels: 2, half: true }, 103: { channels: 2, half: false },  // R16G16, R32G32 SFLOAT
  97: { channels: 4, half: true }, 109: { channels: 4, half: false },  // R16G16B16A16, R32G32B32A32
};

// A table: { size, channels, half, data } with data a Float32Array or a Uint16Array of half
// floats, row-major, first row = texcoord v = 0. From a KTX2 file or raw texels (`--lut raw`).
async function loadTable(url, entry, channels) {
  const hint = "rerun matc with this output directory";
  const bytes = new Uint8Array(await (await fetchChecked(url, hint)).arrayBuffer());
  let table;
  if (entry.file.endsWith(".ktx2")) {
    const readKtx2 = await ktx2Reader();
    let container;
    try {
      container = readKtx2(bytes);
    } catch (error) {
      throw new MatcWebError(`${url}: not a readable KTX2 file (${error.message}); ${hint}`);
    }
    const format = kVkFormats[container.vkFormat];
    if (!format || format.channels !== channels || container.supercompressionScheme !== 0) {
      throw new MatcWebError(`${url}: vkFormat ${container.vkFormat}, supercompression ` +
                             `${container.supercompressionScheme}: not a ${channels}-channel float table of matc's`);
    }
    const level = container.levels[0].levelData;
    const buffer = level.buffer.slice(level.byteOffset, level.byteOffset + level.byteLength);
    table = { size: container.pixelWidth, height: container.pixelHeight, channels, half: format.half,
              data: format.half ? new Uint16Array(buffer) : new Float32Array(buffer) };
  } else if (entry.file.endsWith(".bin")) {
    const half = entry.precision === "f16";
    const texels = bytes.byteLength / (channels * (half ? 2 : 4));
    const size = Math.round(Math.sqrt(texels));
    const buffer = bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength);
    table = { size, height: size, channels, half, data: half ? new Uint16Array(buffer) : new Float32Array(buffer) };
  } else {
    throw new MatcWebError(`${url}: the web integrations read KTX2 and raw tables, not ${entry.file} ` +
                           "(compile with --lut ktx2 or --lut raw)");
  }
  if (table.size !== entry.size || table.height !== entry.size || table.data.length !== entry.size * entry.size * channels) {
    throw new MatcWebError(`${url}: ${table.size}x${table.height} texels, the manifest says ` +
                           `${entry.size}x${entry.size}; ${hint}`);
  }
  return table;
}

// Reads a matc build directory (`matc -o DIR`, with glsl, json and lut among --emit; ltc for area
// lights, coefficient-table for textured metals) and checks its parts belong together.
// `language`: the shader library to read, "glsl" (matc_fresnel.glsl, WebGL) or "wgsl" (WebGPU).
export async function loadMatcBuildFiles(url, { language = "glsl" } = {}) {
  const base = new URL(url.endsWith("/") ? url : `${url}/`, globalThis.location?.href);
  const at = (file) => new URL(file, base).href;
  const manifestUrl = at("matc_manifest.json");
  const manifest = await fetchJson(manifestUrl, "is this a matc output directory (matc -o DIR)?");
  if (manifest.matc_version !== kMatcVersion) {
    throw new MatcWebError(`${manifestUrl}: written by matc ${manifest.matc_version}; this integration reads matc ${kMatcVersion}`);
  }
  const emitted = new Set(manifest.emit ?? []);
  for (const [needed, why] of [[language, "the shader library"], ["lut", "the preintegrated table"],
                               ["json", "the materials' coefficients"]]) {
    if (!emitted.has(needed)) {
      throw new MatcWebError(`${manifestUrl}: the build has no ${needed} output (${why}); compile with ` +
                             `--emit ${needed} among the outputs`);
    }
  }
  const library = await (await fetchChecked(at(`matc_fresnel.${language}`), `compile with --emit ${language}`)).text();
  const sidecar = await fetchJson(at(`${manifest.lut.file}.json`), "compile with --emit lut");
  if (sidecar.basis !== manifest.basis || sidecar.matc_version !== manifest.matc_version) {
    throw new MatcWebError(`${at(manifest.lut.file)}: a table of basis ${sidecar.basis} from matc ` +
                           `${sidecar.matc_version}, but the build is basis ${manifest.basis} from matc ` +
                           `${manifest.matc_version}; rerun matc with this output directory`);
  }
  return {
    url: base.href, manifest, language, library, basis: manifest.basis,
    materialsByName: true,  // loadMaterial(name): the build's <name>.json and snippet
    lut: await loadTable(at(manifest.lut.file), manifest.lut, 4),
    ltc: emitted.has("ltc") ? await loadTable(at(manifest.ltc_table.file), manifest.ltc_table, 4) : null,
    coefficientTable: emitted.has("coefficient-table")
        ? await loadTable(at(manifest.coefficient_table.file), manifest.coefficient_table, 2) : null,
    // A compiled material's coefficients (<name>.json), checked against the build's basis:
    // { name, basis, coefficients: 3 rows (R, G, B) of c_0..c_3 }.
    async loadMaterial(name) {
      const file = at(`${name}.json`);
      const material = await fetchJson(file, `is ${name} one of this build's materials?`);
      const basis = material.basis?.name;
      if (basis !== manifest.basis || material.matc_version !== manifest.matc_version) {
        throw new MatcWebError(`${file}: coefficients of basis ${basis} from matc ${material.matc_version}, ` +
                               `but the build's tables are basis ${manifest.basis} from matc ` +
                               `${manifest.matc_version}: they do not belong together`);
      }
      return { name: material.name, basis, coefficients: checkedRows(material.coefficients, file, "coefficients"),
               coat: material.coat ? await loadCoat(material, at(`${name}.${language}`), file) : null };
    },
  };
}

// The same as loadMatcBuildFiles for materials compiled in the page by the package's compiler
// (`createMatc()`, no `matc -o` step): the shader library from `matc.textOutputs(options)`, the
// package's tables (raw; `tables` names others: { lut, ltc, coefficientTable } URLs of table files
// with their .json beside them, as `matc -o --lut raw` writes them), and `loadMaterial(compiled)`
// taking a CompiledMaterial instead of a name.
export async function compiledMatcBuildFiles(matc, { language = "glsl", options = {}, tables = tableFiles.raw } = {}) {
  const texts = matc.textOutputs(options);
  const library = texts.librarySource(language);
  const table = async (url, channels) => {
    const sidecar = await fetchJson(`${url}.json`, "the package's tables are in its tables/ folder");
    const entry = { file: url, size: sidecar.size?.[0], precision: sidecar.precision };
    return { sidecar, table: await loadTable(url, entry, channels) };
  };
  const lut = await table(tables.lut, 4);
  const basis = lut.sidecar.basis;
  if (lut.sidecar.matc_version !== kMatcVersion) {
    throw new MatcWebError(`${tables.lut}: a table from matc ${lut.sidecar.matc_version}; this integration ` +
                           `reads matc ${kMatcVersion}`);
  }
  const url = `matc:compiled/${language}/${basis}`;
  return {
    url, manifest: { matc_version: kMatcVersion, basis, emit: [language, "json", "lut", "ltc", "coefficient-table"] },
    language, library, basis, lut: lut.table,
    ltc: tables.ltc ? (await table(tables.ltc, 4)).table : null,
    coefficientTable: tables.coefficientTable ? (await table(tables.coefficientTable, 2)).table : null,
    // { name, basis, coefficients, coat } of a CompiledMaterial, as loadMatcBuildFiles' loadMaterial
    // gives for a <name>.json.
    async loadMaterial(compiled) {
      if (typeof compiled?.fresnel !== "function" || !Array.isArray(compiled.coefficients)) {
        throw new MatcWebError("loadMaterial of a compiled build takes a CompiledMaterial (matc.compile())");
      }
      if (compiled.basis !== basis) {
        throw new MatcWebError(`${compiled.name}: compiled with basis ${compiled.basis}, but the tables ` +
                               `are ${basis}`);
      }
      const rows = (values) => values.map((row) => Array.from(row));
      const coat = compiled.coat && {
        weight: compiled.coat.weight, ior: compiled.coat.ior, roughness: compiled.coat.roughness,
        color: Array.from(compiled.coat.color), underCoatCoefficients: rows(compiled.coat.underCoatCoefficients),
        snippet: texts.materialSource(language, compiled),
      };
      return { name: compiled.name, basis, coefficients: rows(compiled.coefficients), coat: coat ?? null };
    },
  };
}

// The files of a build from either source the integrations' loadMatcBuild takes: a build
// directory's URL, or compiledMatcBuildFiles' result (whose language must be `language`).
export async function matcBuildFiles(source, language) {
  if (typeof source === "string" || source instanceof URL) return loadMatcBuildFiles(String(source), { language });
  if (typeof source?.library !== "string" || !source.lut || typeof source.loadMaterial !== "function") {
    throw new MatcWebError("loadMatcBuild takes a build directory's URL or compiledMatcBuildFiles(matc)");
  }
  if (source.language !== language) {
    throw new MatcWebError(`${source.url}: a ${source.language} build; this integration needs ${language} ` +
                           `(compiledMatcBuildFiles(matc, { language: "${language}" }))`);
  }
  return source;
}

// Whether `name` is a material name matc writes (material_name_problem in
// compiler/src/material/parse.cpp): an identifier of at most 64 characters, not starting with "_"
// and without "__" (its snippets' functions are matc_<kind>_<name>, and GLSL reserves "__").
const isSnippetName = (name) => typeof name === "string" && name.length <= 64 &&
                                /^[A-Za-z][A-Za-z0-9_]*$/.test(name) && !name.includes("__");

// A coated material's coat (its <name>.json's coat section) and its shader snippet, whose
// functions the integrations call for both lobes: { weight, ior, roughness, color,
// underCoatCoefficients (3 rows of c_0..c_3: the metal seen through the coat), snippet }.
async function loadCoat(material, snippetUrl, file) {
  const input = material.coat.input ?? {};
  for (const field of ["weight", "ior", "roughness"]) {
    if (typeof input[field] !== "number") throw new MatcWebError(`${file}: coat.input.${field} must be a number`);
  }
  if (!isSnippetName(material.name)) {
    throw new MatcWebError(`${file}: name "${material.name}" is not the identifier matc's snippets use`);
  }
  const snippet = await (await fetchChecked(snippetUrl, "a coated material needs its own shader snippet; " +
                                            "compile with the shader language among --emit")).text();
  return { weight: input.weight, ior: input.ior, roughness: input.roughness, color: rgbOf(input.color),
           underCoatCoefficients: checkedRows(material.coat.under_coat_coefficients, file,
                                              "coat.under_coat_coefficients"),
           snippet };
}

// The name of the glTF vendor extension `matc gltf` writes (docs/gltf.md).
export const kGltfFresnelExtension = "MATC_materials_fresnel";

// A number of `what` in [low, high], or an error naming it.
function checkedNumber(value, low, high, what) {
  if (typeof value !== "number" || !(value >= low && value <= high)) {
    throw new MatcWebError(`${what} must be a number in [${low}, ${high}]`);
  }
  return value;
}

// A coated metal's two-lobe snippet from its extension: the compiler's template filled with the
// extension's values (coated-snippet.mjs), each checked here as the schema has it.
async function extensionCoatedMaterial(build, extension, rows) {
  const what = `${kGltfFresnelExtension}.coat`;
  const coat = extension.coat;
  if (typeof coat !== "object" || coat === null) throw new MatcWebError(`${what} must be an object`);
  const rgb = (value, field) => {
    if (!Array.isArray(value) || value.length !== 3) throw new MatcWebError(`${field} must be 3 numbers in [0, 1]`);
    return value.map((channel) => checkedNumber(channel, 0, 1, field));
  };
  const under = checkedFiniteRows(coat.underCoatCoefficients, what, "underCoatCoefficients");
  const coatRow = coat.coatCoefficients;
  if (!Array.isArray(coatRow) || coatRow.length !== 4 || !finiteRows([coatRow])) {
    throw new MatcWebError(`${what}: coatCoefficients (one row) must be 4 finite numbers`);
  }
  // The library's version: `#define MATC_VERSION n` in GLSL, `const MATC_VERSION: i32 = n;` in WGSL.
  const versionNumber = /(?:#define MATC_VERSION|const MATC_VERSION: i32 =) (\d+)/.exec(build.library)?.[1];
  if (!versionNumber) throw new MatcWebError(`${build.url}: its shader library does not say its MATC_VERSION`);
  const checked = {
    weight: checkedNumber(coat.weight, 0, 1, `${what}.weight`), ior: checkedNumber(coat.ior, 1.05, 3, `${what}.ior`),
    roughness: checkedNumber(coat.roughness, 0, 1, `${what}.roughness`), color: rgb(coat.color, `${what}.color`),
    underCoatCoefficients: under, coatCoefficients: coatRow,
  };
  // Imported when needed: the staged package's (stage.mjs writes it from templates/glsl/ and wgsl/).
  const { kCoatedMaterialGlsl, kCoatedMaterialWgsl } = await import("./templates.mjs");
  const language = build.language ?? "glsl";
  const snippet = coatedSnippet(language === "wgsl" ? kCoatedMaterialWgsl : kCoatedMaterialGlsl, {
    name: extension.name, version: build.manifest.matc_version, versionNumber, coefficients: rows, language,
    colorSpace: String(extension.colorSpace).replace(/[^A-Za-z0-9_]/g, "_"),
    maxError: rgb(extension.maxError, `${kGltfFresnelExtension}.maxError`), coat: checked,
  });
  const { coatCoefficients: _, ...materialCoat } = checked;
  return { name: extension.name, basis: build.basis, coefficients: rows, coat: { ...materialCoat, snippet } };
}

// A glTF material's MATC_materials_fresnel (`extension`) as build.loadMaterial gives a material:
// { name, basis, coefficients, coat }. A bare metal's coefficients are the extension's own. A
// coated metal's two-lobe shader snippet is the build directory's when that compiled the same
// asset (`matc -o DIR asset.glb`: its manifest lists the metal; its <name>.json and snippet,
// checked to hold the extension's coefficients), else matc's template filled with the extension's
// values. Throws a MatcWebError saying why it cannot be used: coefficients of another basis or
// matc version than the build's tables, malformed members, or a build directory whose metal of
// that name differs.
export async function gltfExtensionMaterial(build, extension) {
  const version = build.manifest?.matc_version;
  if (extension?.basis !== build.basis || extension?.matcVersion !== version) {
    throw new MatcWebError(`its ${kGltfFresnelExtension} holds coefficients of basis ${extension?.basis} from ` +
                           `matc ${extension?.matcVersion}; the build's tables are basis ${build.basis} from matc ${version}`);
  }
  if (!isSnippetName(extension.name)) {
    throw new MatcWebError(`its ${kGltfFresnelExtension}.name is not the identifier matc writes`);
  }
  const rows = checkedFiniteRows(extension.coefficients, kGltfFresnelExtension, "coefficients");
  // A textured metal's per-pixel data (Schlick's curve at F0 = 0, or its F0 table), checked here.
  const perPixel = {};
  if (extension.zeroF0Coefficients !== undefined) {
    perPixel.zeroF0Coefficients = checkedZeroF0Rows(extension.zeroF0Coefficients, kGltfFresnelExtension);
  }
  if (extension.f0Table !== undefined) {
    perPixel.f0Table = checkedF0Table(extension.f0Table, Boolean(extension.coat), `${kGltfFresnelExtension}.f0Table`);
  }
  if (!extension.coat) {
    return { name: extension.name, basis: build.basis, coefficients: rows, coat: null, ...perPixel };
  }
  const inDirectory = build.materialsByName &&
                      (build.manifest.materials ?? []).some((material) => material?.name === extension.name);
  if (!inDirectory) return { ...(await extensionCoatedMaterial(build, extension, rows)), ...perPixel };
  const material = await build.loadMaterial(extension.name);
  const same = (a, b) => JSON.stringify(a) === JSON.stringify(b);
  if (!material.coat || !same(material.coefficients, rows) ||
      !same(material.coat.underCoatCoefficients, extension.coat.underCoatCoefficients)) {
    throw new MatcWebError(`the build directory's ${extension.name} is not this asset's metal (its coefficients ` +
                           "differ): compile the same asset with the same options into it");
  }
  return { ...material, ...perPixel };
}

// The glTF material `index` of the asset `json` alone, as a glTF asset the importer reads (a
// material needs no other part of the asset to be compiled). Loader bookkeeping (keys starting
// with "_", a loader's `index`) is left out.
function gltfMaterialAsset(json, index) {
  const { index: _, ...material } = json.materials[index];
  return JSON.stringify({ asset: { version: "2.0" }, materials: [material], extensionsUsed: json.extensionsUsed ?? [] },
                        (key, value) => (key.startsWith("_") ? undefined : value));
}

const isGltfMetal = (material) => (material.pbrMetallicRoughness?.metallicFactor ?? 1) > 0;

// Whether a glTF metal's metalness varies from 1: a metallicFactor below 1 or a
// metallicRoughnessTexture (whose blue channel scales it per pixel). Such a material is glTF's
// metal-rough model per pixel: matc's metal mixed with the engine's dielectric (docs/gltf.md).
export const isGltfMetalRough = (material) => {
  const pbr = material.pbrMetallicRoughness ?? {};
  return (pbr.metallicFactor ?? 1) < 1 || pbr.metallicRoughnessTexture !== undefined;
};

// What the engines' glTF loaders (three/matc-gltf.mjs, babylon/matc-gltf.mjs) make of an asset's
// materials: `metalOf(index)` resolves to { metal (as build.loadMaterial gives it), from:
// "extension" | "compiled", source: useMatcFresnel's }, or null for a material that stays the
// engine's. A textured metal follows the engine's base colour (factor times texture) per pixel:
// of Schlick's curve (no edge colour, no coat) with the source { schlick }, under an edge colour
// or a coat with { material, f0Table }; one whose extension carries neither (compiled in another
// working space) is shaded at its factor, with `note(index, why)`. A metal's
// MATC_materials_fresnel is used when it fits the build; otherwise `matc` (createMatc(), when
// given) compiles the glTF material with `compile`'s options. A metal matc cannot take gets
// `warn(index, why)`; a non-metal nothing. Each index is resolved once.
export function gltfMetals({ matc = null, build, compile = {}, json, warn, note = warn }) {
  const found = new Map();
  const textured = (index) => json.materials[index].pbrMetallicRoughness?.baseColorTexture !== undefined;
  // `perPixel`: the extension's (or the metal's, from gltfExtensionMaterial) zeroF0Coefficients or f0Table.
  const withSource = (index, metal, from, perPixel) => {
    if (!textured(index)) return { metal, from, source: { material: metal } };
    if (perPixel?.zeroF0Coefficients) {
      return { metal, from, source: { schlick: { basis: metal.basis, zeroF0Coefficients: perPixel.zeroF0Coefficients } } };
    }
    if (perPixel?.f0Table) return { metal, from, source: { material: metal, f0Table: perPixel.f0Table } };
    note(index, `its baseColorTexture is not followed (its ${kGltfFresnelExtension} has no f0Table: ` +
                "compiled in a working space other than lin_rec709); shaded at its baseColorFactor");
    return { metal, from, source: { material: metal } };
  };
  // `matc gltf` in the page: the importer decides which metals follow their texture per pixel, and
  // writes their zeroF0Coefficients, as for an asset written offline.
  const compileInPage = async (index) => {
    try {
      const asset = matc.compileGltf(gltfMaterialAsset(json, index), "asset.gltf", compile);
      const [compiled] = asset.materials;
      if (!compiled) return null;
      const written = JSON.parse(new TextDecoder().decode(asset.bytes));
      const extension = written.materials[0].extensions[kGltfFresnelExtension];
      return withSource(index, await build.loadMaterial(compiled), "compiled", extension);
    } catch (error) {
      // A value matc refuses, options that do not fit the build. (Not a metal compiles to no
      // material: the engine's material stays, silently.)
      warn(index, error.message);
      return null;
    }
  };
  const resolve = async (index) => {
    const material = json.materials[index];
    const extension = material.extensions?.[kGltfFresnelExtension];
    let refusal = null;
    if (extension && isGltfMetal(material)) {
      try {
        const metal = await gltfExtensionMaterial(build, extension);
        return withSource(index, metal, "extension", metal);
      } catch (error) {
        refusal = error.message;
      }
    }
    if (matc) return compileInPage(index);
    if (isGltfMetal(material)) {
      warn(index, refusal ?? `no ${kGltfFresnelExtension} (matc gltf writes it) and no compiler in the page (matc)`);
    }
    return null;
  };
  return {
    metalOf(index) {
      if (!found.has(index)) found.set(index, resolve(index));
      return found.get(index);
    },
  };
}

// Checks a glTF loader's options (matc optional, build required).
export function checkGltfLoaderOptions(matc, build, what) {
  if ((matc !== null && typeof matc?.parseMaterials !== "function") || typeof build?.loadMaterial !== "function") {
    throw new MatcWebError(`${what} takes { build: await loadMatcBuild(...), matc?: await createMatc() }`);
  }
}

// A compiled material's coefficient rows (R, G, B: c_0..c_3), or an error naming `field` of `file`.
function checkedRows(rows, file, field) {
  if (!Array.isArray(rows) || rows.length !== 3 || rows.some((row) => row.length !== 4)) {
    throw new MatcWebError(`${file}: ${field} must be 3 rows of 4 numbers`);
  }
  return rows;
}

// Whether every value of coefficient rows is a finite number.
const finiteRows = (rows) => rows.every((row) => row.every((value) => typeof value === "number" && Number.isFinite(value)));

// Coefficient rows (checkedRows) of finite numbers, or an error naming `what`.`field`.
function checkedFiniteRows(rows, what, field) {
  checkedRows(rows, what, field);
  if (!finiteRows(rows)) throw new MatcWebError(`${what}.${field} must be finite numbers`);
  return rows;
}

// Coefficient rows of a Schlick curve at F0 = 0 (c_0 = 0, c_1 = 1 per channel, finite c_2, c_3),
// or an error naming `what`.
function checkedZeroF0Rows(rows, what) {
  checkedRows(rows, what, "zeroF0Coefficients");
  if (!finiteRows(rows) || rows.some((row) => row[0] !== 0 || row[1] !== 1)) {
    throw new MatcWebError(`${what}: zeroF0Coefficients must be rows [0, 1, c_2, c_3] of finite numbers`);
  }
  return rows;
}

// The entries of an F0 table (MATC_materials_fresnel's f0Table, docs/gltf.md): entry i is the metal
// compiled at F0 = (i / (kF0TableEntries - 1))^4.
export const kF0TableEntries = 33;

// An F0 table ({ coefficients, underCoatCoefficients: kF0TableEntries entries of 3 rows of c_0..c_3;
// the latter only under a coat, `coated`}), or an error naming `what`.
function checkedF0Table(table, coated, what) {
  const entries = (value, field) => {
    if (!Array.isArray(value) || value.length !== kF0TableEntries) {
      throw new MatcWebError(`${what}.${field} must be ${kF0TableEntries} entries of 3 rows of 4 numbers`);
    }
    for (const entry of value) checkedFiniteRows(entry, what, field);
  };
  entries(table?.coefficients, "coefficients");
  if (coated !== (table.underCoatCoefficients !== undefined)) {
    throw new MatcWebError(`${what}: ${coated ? "a coated metal's table needs" : "a bare metal's table has no"} ` +
                           "underCoatCoefficients");
  }
  if (coated) entries(table.underCoatCoefficients, "underCoatCoefficients");
  return table;
}

// An F0 table as the texels of an RGBA float texture of kF0TableEntries x 6, row-major (texel
// (i, c) entry i's row of channel c in air, (i, 3 + c) under the coat; zero for a bare metal), as
// matc's MATC_COEFFICIENTS_FROM_F0_TABLE and MATC_UNDER_COAT_FROM_F0_TABLE read it.
export function f0TableTexels(table) {
  const texels = new Float32Array(kF0TableEntries * 6 * 4);
  const put = (entries, firstRow) => entries?.forEach((rows, i) => rows.forEach((row, channel) => {
    texels.set(row, ((firstRow + channel) * kF0TableEntries + i) * 4);
  }));
  put(table.coefficients, 0);
  put(table.underCoatCoefficients, 3);
  return texels;
}

// Checks the areaLights option against what a coated material takes in an integration
// (`allowed`): the quality level's area lights take bare metals.
export function checkCoatedAreaLights(material, areaLights, allowed = ["matc", "engine"]) {
  if (allowed.includes(areaLights)) return;
  const why = areaLights === "quality" ? "the quality-level area lights take bare metals"
                                       : `its coat lobe needs matc's LTC on rect lights (areaLights "${areaLights}")`;
  throw new MatcWebError(`${material.name} is coated: ${why}; use areaLights ` +
                         allowed.map((value) => `"${value}"`).join(" or "));
}

// A colour option of a source (reflectivity, edgeTint): [r, g, b], one grey value, or 1 when absent.
export function rgbOf(value) {
  return Array.isArray(value) ? value : [value ?? 1, value ?? 1, value ?? 1];
}

// Checks the areaLights option against the values an integration supports.
export function checkAreaLights(areaLights, allowed = ["matc", "quality", "engine"]) {
  if (!allowed.includes(areaLights)) {
    throw new MatcWebError(`areaLights: "${areaLights}"; allowed: ${allowed.map((value) => `"${value}"`).join(", ")}`);
  }
}

// Checks that a source of coefficients (see the integrations' useMatcFresnel) fits the build;
// returns its kind: "schlick", "material", "table" or "baked".
export function sourceKind(build, source) {
  if (source?.schlick) {
    const { basis, zeroF0Coefficients } = source.schlick;
    if (basis !== build.basis) {
      throw new MatcWebError(`schlick: coefficients of basis ${basis}, the build's tables are ${build.basis}`);
    }
    checkedZeroF0Rows(zeroF0Coefficients, "schlick");
    return "schlick";
  }
  if (source?.f0Table) {
    if (!source.material) throw new MatcWebError("an F0 table (f0Table) comes with its { material }");
    checkedF0Table(source.f0Table, Boolean(source.material.coat), "f0Table");
  }
  if (source?.material) {
    if (source.material.basis !== build.basis) {
      throw new MatcWebError(`${source.material.name}: coefficients of basis ${source.material.basis}, ` +
                             `the build's tables are ${build.basis}`);
    }
    return source.f0Table ? "f0Table" : "material";
  }
  if (source?.reflectivityMap || source?.edgeTintMap) {
    if (!source.reflectivityMap || !source.edgeTintMap) {
      throw new MatcWebError("a textured metal needs both reflectivityMap and edgeTintMap");
    }
    if (!build.coefficientTable) {
      throw new MatcWebError(`${build.url}: textured metals need the coefficient table; compile with ` +
                             "--emit coefficient-table among the outputs");
    }
    return "table";
  }
  if (source?.baked) {
    if (!source.baked.c2Map || !source.baked.c3Map) {
      throw new MatcWebError("baked coefficients need c2Map and c3Map (matc bake)");
    }
    if (source.baked.basis && source.baked.basis !== build.basis) {
      throw new MatcWebError(`baked coefficients of basis ${source.baked.basis}, the build's tables are ${build.basis}`);
    }
    return "baked";
  }
  throw new MatcWebError("useMatcFresnel needs { material }, { material, f0Table }, { schlick }, " +
                         "{ reflectivityMap, edgeTintMap } or { baked }");
}
