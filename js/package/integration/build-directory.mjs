// A matc build in a browser: a build directory (`matc -o DIR`: manifest, shader library, tables,
// compiled materials, each checked against the others), or the same made from materials compiled
// in the page by the package's WebAssembly compiler. Engine-neutral: tables come back as typed
// arrays for the engine's own texture class. KTX2 containers are read with ktx-parse (npm, the
// reader three.js bundles), imported when a KTX2 table is read: raw tables (the package's) need
// nothing else.
import { tableFiles } from "../tables.mjs";
import { checkedRows } from "./coefficient-rows.mjs";
import { MatcWebError, kMatcVersion, quoted } from "./errors.mjs";
import { rgbOf } from "./sources.mjs";

async function ktx2Reader() {
  try {
    return (await import("ktx-parse")).read;
  } catch (error) {
    throw new MatcWebError(`KTX2 tables need the ktx-parse package (${error.message}); install it, or ` +
                           "compile with --lut raw");
  }
}

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

// A table: { size (its width), height, channels, half, data } with data a Float32Array or a Uint16Array of half
// floats, row-major, first row = texcoord v = 0. From a KTX2 file or raw texels (`--lut raw`).
// `entry`: { file, size, precision } of a square table (`layers` of them side by side), or
// { file, width, height, precision } of another shape (a filmed metal's table).
async function loadTable(url, entry, channels, layers = 1) {
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
    const bytesPerValue = half ? 2 : 4;
    if (bytes.byteLength % (channels * bytesPerValue) !== 0) {
      throw new MatcWebError(`${url}: ${bytes.byteLength} bytes, not whole ${channels}-channel texels; ${hint}`);
    }
    const texels = bytes.byteLength / (channels * bytesPerValue);
    const height = entry.height ?? Math.round(Math.sqrt(texels / layers));
    const buffer = bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength);
    table = { size: Math.round(texels / height), height, channels, half,
              data: half ? new Uint16Array(buffer) : new Float32Array(buffer) };
  } else {
    throw new MatcWebError(`${url}: the web integrations read KTX2 and raw tables, not ${entry.file} ` +
                           "(compile with --lut ktx2 or --lut raw)");
  }
  const width = entry.width ?? entry.size * layers;
  const height = entry.height ?? entry.size;
  if (table.size !== width || table.height !== height || table.data.length !== width * height * channels) {
    throw new MatcWebError(`${url}: ${table.size}x${table.height} texels, the manifest says ` +
                           `${width}x${height}; ${hint}`);
  }
  return table;
}

// A per-material build's manifest.lut_layers: the bases of its table's layers, in order.
function checkedLayers(layers, where) {
  if (!Array.isArray(layers) || layers.length < 2 || !layers.every((basis) => /^[a-z0-9]+$/.test(basis))) {
    throw new MatcWebError(`${where}: a per-material build (basis auto) without its lut_layers; rerun matc`);
  }
  return layers;
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
  // A per-material build (matc --basis auto): the table holds a layer per basis side by side
  // (docs/lut.md) and each material names its basis, one of them.
  const layers = manifest.basis === "auto" ? checkedLayers(manifest.lut_layers, manifestUrl) : null;
  if (sidecar.basis !== manifest.basis || sidecar.matc_version !== manifest.matc_version) {
    throw new MatcWebError(`${at(manifest.lut.file)}: a table of basis ${sidecar.basis} from matc ` +
                           `${sidecar.matc_version}, but the build is basis ${manifest.basis} from matc ` +
                           `${manifest.matc_version}; rerun matc with this output directory`);
  }
  return {
    url: base.href, manifest, language, library, basis: manifest.basis, layers,
    materialsByName: true,  // loadMaterial(name): the build's <name>.json and snippet
    lut: await loadTable(at(manifest.lut.file), manifest.lut, 4, layers?.length ?? 1),
    ltc: emitted.has("ltc") ? await loadTable(at(manifest.ltc_table.file), manifest.ltc_table, 4) : null,
    coefficientTable: emitted.has("coefficient-table")
        ? await loadTable(at(manifest.coefficient_table.file), manifest.coefficient_table, 2) : null,
    // A compiled material's coefficients (<name>.json), checked against the build's basis:
    // { name, basis, coefficients: 3 rows (R, G, B) of c_0..c_3 }.
    async loadMaterial(name) {
      const file = at(`${name}.json`);
      const material = await fetchJson(file, `is ${quoted(name)} one of this build's materials?`);
      const basis = material.basis?.name;
      if (!(layers ? layers.includes(basis) : basis === manifest.basis) ||
          material.matc_version !== manifest.matc_version) {
        throw new MatcWebError(`${file}: coefficients of basis ${quoted(basis)} from matc ${quoted(material.matc_version)}, ` +
                               `but the build's tables are basis ${manifest.basis} from matc ` +
                               `${manifest.matc_version}: they do not belong together`);
      }
      const film = material.film_table
          ? await loadFilm(material, manifest, at, file) : null;
      return { name: material.name, basis, coefficients: checkedRows(material.coefficients, file, "coefficients"),
               coat: material.coat ? await loadCoat(material, at(`${name}.${language}`), file) : null, film };
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
  // A table's sidecar gives its height; a layered one (basis auto) its layers' bases too.
  const table = async (url, channels) => {
    const sidecar = await fetchJson(`${url}.json`, "the package's tables are in its tables/ folder");
    const layers = sidecar.basis === "auto"
        ? checkedLayers(sidecar.layers?.map?.((layer) => layer?.basis), `${url}.json`) : null;
    const entry = { file: url, size: sidecar.size?.[1] ?? sidecar.size?.[0], precision: sidecar.precision };
    return { sidecar, layers, table: await loadTable(url, entry, channels, layers?.length ?? 1) };
  };
  const lut = await table(tables.lut, 4);
  const { basis, matc_version: version } = lut.sidecar;
  if (version !== kMatcVersion) {
    throw new MatcWebError(`${tables.lut}: a table from matc ${version}; this integration ` +
                           `reads matc ${kMatcVersion}`);
  }
  if (basis !== texts.basis) {
    // A per-material library reads a table of a layer per basis, a one-basis library one layer.
    throw new MatcWebError(`${tables.lut}: a table of basis ${basis}, but options.basis gives basis ` +
                           `${texts.basis}; give tables of that basis (matc --basis ${texts.basis} ` +
                           "--lut raw -o DIR) or leave options.basis out for the package's");
  }
  const layers = lut.layers;
  const url = `matc:compiled/${language}/${basis}`;
  return {
    url, manifest: { matc_version: kMatcVersion, basis, ...(layers ? { lut_layers: layers } : {}),
                     emit: [language, "json", "lut", "ltc", "coefficient-table"] },
    language, library, basis, layers, lut: lut.table,
    ltc: tables.ltc ? (await table(tables.ltc, 4)).table : null,
    coefficientTable: tables.coefficientTable ? (await table(tables.coefficientTable, 2)).table : null,
    // { name, basis, coefficients, coat } of a CompiledMaterial, as loadMatcBuildFiles' loadMaterial
    // gives for a <name>.json.
    async loadMaterial(compiled) {
      if (typeof compiled?.fresnel !== "function" || !Array.isArray(compiled.coefficients)) {
        throw new MatcWebError("loadMaterial of a compiled build takes a CompiledMaterial (matc.compile())");
      }
      if (!(layers ? layers.includes(compiled.basis) : compiled.basis === basis)) {
        throw new MatcWebError(`${compiled.name}: compiled with basis ${compiled.basis}, but the tables ` +
                               `are ${basis}${layers ? ` (${layers.join(", ")})` : ""}`);
      }
      const rows = (values) => values.map((row) => Array.from(row));
      const coat = compiled.coat && {
        weight: compiled.coat.weight, ior: compiled.coat.ior, roughness: compiled.coat.roughness,
        color: Array.from(compiled.coat.color), underCoatCoefficients: rows(compiled.coat.underCoatCoefficients),
        snippet: texts.materialSource(language, compiled),
      };
      // A filmed metal's table as the library holds it (f32).
      const filmTable = compiled.filmTable;
      const film = filmTable && {
        table: { size: filmTable.width, height: filmTable.height, channels: 4, half: false, data: filmTable.texels },
      };
      return { name: compiled.name, basis: compiled.basis, coefficients: rows(compiled.coefficients),
               coat: coat ?? null, film: film ?? null };
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

// Names whose snippets would define one of the shared library's identifiers again ("sum" would
// make matc_fresnel_sum): kNamesTakenByLibrary in compiler/src/base/identifier_names.h, which
// GeneratedIdentifiers.JavaScriptListIsTheLibrarys holds equal to this one.
const kNamesTakenByLibrary = new Set([
  "f82", "following", "following_f82", "from_baked", "from_f0", "from_f0_entries", "from_f0_table",
  "from_table", "from_table_texture", "preintegrated", "preintegrated_sum", "sum", "sum_f82",
]);

// Whether `name` is a material name matc writes (material_name_problem in
// compiler/src/material/parse.cpp): an identifier of at most 64 characters, not starting with "_"
// and without "__" (its snippets' functions are matc_<kind>_<name>, and GLSL reserves "__"), and
// none of the library's.
export const isSnippetName = (name) => typeof name === "string" && name.length <= 64 &&
                                /^[A-Za-z][A-Za-z0-9_]*$/.test(name) && !name.includes("__") &&
                                !kNamesTakenByLibrary.has(name);

// The width and height of a filmed metal's table (FilmTable in runtime/include/matc/runtime/film_table.h).
export const kFilmTableWidth = 65;
export const kFilmTableHeight = 18;

// A filmed metal's table (<name>.film.<ext>, the file the manifest lists for it, at the table's
// precision; docs/thin-film.md): { table }, which the integrations sample through the library's
// matc_film_* functions (the material's snippet returns the texels as they are).
async function loadFilm(material, manifest, at, file) {
  const entry = (manifest.materials ?? []).find((listed) => listed?.name === material.name);
  const tableFile = entry?.files?.map?.((written) => written?.file)
                        .find((name) => typeof name === "string" && name.startsWith(`${material.name}.film.`));
  if (!tableFile) {
    throw new MatcWebError(`${file}: a filmed metal, but the manifest lists no ${quoted(`${material.name}.film.<ext>`)} ` +
                           "(its own table); compile with --emit lut among the outputs");
  }
  return { table: await loadTable(at(tableFile), { file: tableFile, width: kFilmTableWidth, height: kFilmTableHeight,
                                                  precision: manifest.lut?.precision }, 4) };
}

// A coated material's coat (its <name>.json's coat section) and its shader snippet, whose
// functions the integrations call for both lobes: { weight, ior, roughness, color,
// underCoatCoefficients (3 rows of c_0..c_3: the metal seen through the coat), snippet }.
async function loadCoat(material, snippetUrl, file) {
  const input = material.coat.input ?? {};
  for (const field of ["weight", "ior", "roughness"]) {
    if (typeof input[field] !== "number") throw new MatcWebError(`${file}: coat.input.${field} must be a number`);
  }
  if (!isSnippetName(material.name)) {
    throw new MatcWebError(`${file}: name ${quoted(material.name)} is not the identifier matc's snippets use`);
  }
  const snippet = await (await fetchChecked(snippetUrl, "a coated material needs its own shader snippet; " +
                                            "compile with the shader language among --emit")).text();
  return { weight: input.weight, ior: input.ior, roughness: input.roughness, color: rgbOf(input.color),
           underCoatCoefficients: checkedRows(material.coat.under_coat_coefficients, file,
                                              "coat.under_coat_coefficients"),
           snippet };
}
