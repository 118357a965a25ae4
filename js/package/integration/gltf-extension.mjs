// glTF assets in the engines' loaders: a metal's MATC_materials_fresnel (written by `matc gltf`)
// read into what build.loadMaterial gives, its coated snippet from a build directory or matc's
// template, and which of an asset's materials become matc metals (gltfMetals).
import { coatedSnippet } from "../coated-snippet.mjs";
import { buildBases, holdsBasis } from "./basis-layers.mjs";
import { checkedFiniteRows, checkedZeroF0Rows, finiteRows } from "./coefficient-rows.mjs";
import { MatcWebError, quoted } from "./errors.mjs";
import { checkedF0Table } from "./f0-table.mjs";
import { isSnippetName, kFilmTableHeight, kFilmTableWidth } from "./build-directory.mjs";

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
async function extensionCoatedMaterial(build, extension, rows, film = null) {
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
  const templates = await import("../templates.mjs");
  const language = build.language ?? "glsl";
  const template = film ? (language === "wgsl" ? templates.kFilmCoatedMaterialWgsl : templates.kFilmCoatedMaterialGlsl)
                        : (language === "wgsl" ? templates.kCoatedMaterialWgsl : templates.kCoatedMaterialGlsl);
  const snippet = coatedSnippet(template, {
    name: extension.name, version: build.manifest.matc_version, versionNumber, coefficients: rows, language,
    colorSpace: String(extension.colorSpace).replace(/[^A-Za-z0-9_]/g, "_"),
    maxError: rgb(extension.maxError, `${kGltfFresnelExtension}.maxError`), coat: checked, film,
  });
  const { coatCoefficients: _, ...materialCoat } = checked;
  return { name: extension.name, basis: extension.basis, coefficients: rows, coat: { ...materialCoat, snippet },
           film: film ?? null };
}

// A filmed metal's film from its extension (docs/thin-film.md): { weight, ior, thickness, table },
// the table's texels (base64 of little-endian float32 RGB, row after row: `matc gltf` writes them)
// as the 65 x 18 RGBA texels its file holds (alpha 1), each member checked as the schema has it.
function extensionFilm(film) {
  const what = `${kGltfFresnelExtension}.film`;
  if (typeof film !== "object" || film === null) throw new MatcWebError(`${what} must be an object`);
  const table = film.table ?? {};
  const texels = kFilmTableWidth * kFilmTableHeight;
  const base64 = typeof table.texels === "string" && /^[A-Za-z0-9+/]*={0,2}$/.test(table.texels) ? table.texels : null;
  const bytes = base64 !== null && base64.length === Math.ceil((texels * 12) / 3) * 4
      ? Uint8Array.from(atob(base64), (character) => character.charCodeAt(0)) : null;
  if (table.width !== kFilmTableWidth || table.height !== kFilmTableHeight || bytes?.length !== texels * 12) {
    throw new MatcWebError(`${what}.table must be ${kFilmTableWidth} x ${kFilmTableHeight} texels, their RGB as ` +
                           `${texels * 12} bytes of little-endian float32 in base64`);
  }
  const view = new DataView(bytes.buffer);
  const data = new Float32Array(texels * 4);
  for (let texel = 0; texel < texels; ++texel) {
    for (let c = 0; c < 3; ++c) data[4 * texel + c] = view.getFloat32(12 * texel + 4 * c, true);
    data[4 * texel + 3] = 1;
  }
  // Finite, not within [0, 1]: a colour outside the working space's gamut stays (docs/color-spaces.md).
  if (!data.every(Number.isFinite)) throw new MatcWebError(`${what}.table.texels must be finite numbers`);
  return { weight: checkedNumber(film.weight, 0, 1, `${what}.weight`), ior: checkedNumber(film.ior, 1, 3, `${what}.ior`),
           thickness: checkedNumber(film.thickness, 0, 2000, `${what}.thickness`),
           table: { size: kFilmTableWidth, height: kFilmTableHeight, channels: 4, half: false, data } };
}

// A glTF material's MATC_materials_fresnel (`extension`) as build.loadMaterial gives a material:
// { name, basis, coefficients, coat, film? }. A bare metal's coefficients are the extension's own. A
// coated metal's two-lobe shader snippet is the build directory's when that compiled the same
// asset (`matc -o DIR asset.glb`: its manifest lists the metal; its <name>.json and snippet,
// checked to hold the extension's coefficients), else matc's template filled with the extension's
// values. Throws a MatcWebError saying why it cannot be used: coefficients of another basis or
// matc version than the build's tables, malformed members, or a build directory whose metal of
// that name differs.
export async function gltfExtensionMaterial(build, extension) {
  const version = build.manifest?.matc_version;
  if (!holdsBasis(build, extension?.basis) || extension?.matcVersion !== version) {
    throw new MatcWebError(`its ${kGltfFresnelExtension} holds coefficients of basis ${quoted(extension?.basis)} from ` +
                           `matc ${quoted(extension?.matcVersion)}; the build's tables are basis ` +
                           `${buildBases(build).join(", ")} from matc ${version}`);
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
  const film = extension.film === undefined ? null : extensionFilm(extension.film);
  if (film && Object.keys(perPixel).length > 0) {
    throw new MatcWebError(`its ${kGltfFresnelExtension} has a film with per-pixel data, which matc does ` +
                           "not write (a film's table holds one metal)");
  }
  if (film && !extension.coat) {
    return { name: extension.name, basis: extension.basis, coefficients: rows, coat: null, film };
  }
  if (!extension.coat) {
    return { name: extension.name, basis: extension.basis, coefficients: rows, coat: null, ...perPixel };
  }
  const inDirectory = build.materialsByName &&
                      (build.manifest.materials ?? []).some((material) => material?.name === extension.name);
  // A film under the coat: its table (the base lobe) from the extension, its snippet the
  // film-under-a-coat template's.
  if (!inDirectory) return { ...(await extensionCoatedMaterial(build, extension, rows, film)), ...perPixel };
  const material = await build.loadMaterial(extension.name);
  const same = (a, b) => JSON.stringify(a) === JSON.stringify(b);
  if (!material.coat || !same(material.coefficients, rows) || Boolean(material.film) !== Boolean(film) ||
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

// Whether a material's KHR_materials_iridescence is a film matc compiles as the bare metal (its
// has_visible_film; the importer takes the film at iridescenceThicknessMaximum): no coverage, an
// index of 1 (air; under a clear coat the importer leaves it out) or no thickness, or under a full
// clear coat the coat's own index (more coat: docs/thin-film.md, "Under a coat"). glTF's defaults:
// factor 0, index 1.3, maximum 400 nm; a clear coat's factor 0 and index 1.5.
const hasBareFilm = (material) => {
  const film = material.extensions?.KHR_materials_iridescence;
  const coat = material.extensions?.KHR_materials_clearcoat;
  const ior = film?.iridescenceIor ?? 1.3;
  const fullCoat = (coat?.clearcoatFactor ?? 0) >= 1;
  const coatIor = coat?.extensions?.KHR_materials_clearcoat_ior?.clearcoatIor ?? 1.5;
  return typeof film === "object" && film !== null &&
         ((film.iridescenceFactor ?? 0) === 0 || ior === 1 || (film.iridescenceThicknessMaximum ?? 400) === 0 ||
          (fullCoat && ior === coatIor));
};

// Whether a glTF metal's metalness varies from 1: a metallicFactor below 1 or a
// metallicRoughnessTexture (whose blue channel scales it per pixel). Such a material is glTF's
// metal-rough model per pixel: matc's metal mixed with the engine's dielectric (docs/gltf.md).
export const isGltfMetalRough = (material) => {
  const pbr = material.pbrMetallicRoughness ?? {};
  return (pbr.metallicFactor ?? 1) < 1 || pbr.metallicRoughnessTexture !== undefined;
};

// What the engines' glTF loaders (three/matc-gltf.mjs, babylon/matc-gltf.mjs) make of an asset's
// materials: `metalOf(index)` resolves to { metal (as build.loadMaterial gives it), from:
// "extension" | "compiled", source: useMatcFresnel's, metalRough: useMatcFresnel's option, set for
// a metal (bare or coated) whose metalness is partial or textured, bareFilm: useMatcFresnel's
// option, set for a bare metal under a KHR_materials_iridescence that shows nothing (index 1, 0 nm
// or no coverage: matc compiles it bare, and it takes the engine's iridescence's place) }, or null for a material that stays the
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
  const sourceOf = (index, metal, perPixel) => {
    if (!textured(index)) return { material: metal };
    if (perPixel?.zeroF0Coefficients) {
      return { schlick: { basis: metal.basis, zeroF0Coefficients: perPixel.zeroF0Coefficients } };
    }
    if (perPixel?.f0Table) return { material: metal, f0Table: perPixel.f0Table };
    if (metal.film) {
      note(index, "its baseColorTexture is not followed (a filmed metal's table holds the film over one metal); " +
                  "shaded at its baseColorFactor");
      return { material: metal };
    }
    note(index, `its baseColorTexture is not followed (its ${kGltfFresnelExtension} has no f0Table: ` +
                "compiled in a working space other than lin_rec709); shaded at its baseColorFactor");
    return { material: metal };
  };
  // metalRough: glTF's metal-rough mix per pixel (under a coat too: the engine's dielectric
  // through the coat as glTF layers a clear coat).
  const withSource = (index, metal, from, perPixel) => ({
    metal, from, source: sourceOf(index, metal, perPixel), metalRough: isGltfMetalRough(json.materials[index]),
    bareFilm: !metal.film && hasBareFilm(json.materials[index]),
  });
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
