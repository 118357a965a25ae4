// matc in WebAssembly: read, compile and evaluate materials, and write their shader texts, in a
// page or in Node, with the native library's code (docs/web.md). No global state: each
// createMatc() is an instance of its own.
//
//   import { createMatc } from "matc";
//   const matc = await createMatc();
//   const gold = matc.compile(matc.parseMaterial({ name: "gold", spectral: { preset: "Au" } }));
//   gold.coefficients;                    // [Float64Array(4) x 3]: c_0..c_3 for R, G, B
//   matc.textOutputs().materialSource("glsl", gold);
import createMatcModule from "./matc.mjs";

export const version = "@MATC_VERSION@";

// A material the library refused, or an argument out of range. `kind`: "material" (the input's
// diagnostics, each as the CLI prints it, in `diagnostics`), "argument", "memory" or "internal".
export class MatcError extends Error {
  constructor(error) {
    super(error.message);
    this.name = "MatcError";
    this.kind = error.kind;
    this.diagnostics = error.diagnostics ?? [];
  }
}

function unwrapped(result) {
  if (result.error) throw new MatcError(result.error);
  return result.value;
}

// A document's text: a string, or its bytes (a Uint8Array or an ArrayBuffer, as fetched), which
// reach the parser unchanged (a string cannot hold bytes that are not UTF-8).
function checkedText(value, argument) {
  if (value instanceof ArrayBuffer) return new Uint8Array(value);
  if (value instanceof Uint8Array) return value;
  return checkedString(value, argument);
}

// The files an input names: undefined, or a plain object of name -> text or bytes.
function checkedFiles(files) {
  if (files === undefined || files === null) return undefined;
  if (typeof files !== "object" || Array.isArray(files) || files instanceof Uint8Array) {
    throw new TypeError("files: an object of name -> text or bytes");
  }
  const checked = {};
  for (const [name, value] of Object.entries(files)) checked[name] = checkedText(value, `files["${String(name).slice(0, 64)}"]`);
  return checked;
}

function checkedString(value, argument) {
  if (typeof value !== "string") throw new TypeError(`${argument}: a string, not ${typeof value}`);
  return value;
}

// Cosines and other arguments: a number, an array or a typed array of numbers.
function numbers(values, argument) {
  if (typeof values === "number") return [values];
  if (Array.isArray(values) || ArrayBuffer.isView(values)) {
    if (ArrayBuffer.isView(values) && !(values instanceof Float64Array || values instanceof Float32Array)) {
      throw new TypeError(`${argument}: a Float64Array, a Float32Array or an array of numbers`);
    }
    for (let i = 0; i < values.length; ++i) {
      if (typeof values[i] !== "number") throw new TypeError(`${argument}: element ${i} is not a number`);
    }
    return values;
  }
  throw new TypeError(`${argument}: a number or an array of numbers`);
}

const kOptionNames = { basis: "basis", colorSpace: "color_space", gamutMapping: "gamut_mapping" };

function optionStrings(options) {
  if (options === undefined || options === null) options = {};
  if (typeof options !== "object") throw new TypeError("options: an object");
  for (const key of Object.keys(options)) {
    if (!(key in kOptionNames)) {
      throw new TypeError(`options: unknown option '${String(key).slice(0, 64)}'; ` +
                          `one of ${Object.keys(kOptionNames).join(", ")}`);
    }
  }
  return Object.keys(kOptionNames).map((key) => {
    const value = options[key] ?? "";
    return checkedString(value, `options.${key}`);
  });
}

// Deletes the native object behind a JS one when it is collected (or at dispose()).
const collected = new FinalizationRegistry((handle) => handle.delete());

class Handle {
  #handle;
  constructor(handle) {
    this.#handle = handle;
    collected.register(this, handle, this);
  }
  get handle() {
    if (!this.#handle) throw new MatcError({ kind: "argument", message: "used after dispose()" });
    return this.#handle;
  }
  // Frees the native object now rather than when the garbage collector runs.
  dispose() {
    if (!this.#handle) return;
    collected.unregister(this);
    this.#handle.delete();
    this.#handle = null;
  }
}

export class Material extends Handle {
  constructor(handle) {
    super(handle);
    Object.assign(this, handle.describe());  // name, model, path, json, coated, diagnostics
  }
}

export class CompiledMaterial extends Handle {
  constructor(handle, material) {
    super(handle);
    this.material = material;
    // name, basis, coefficients, f0, f82, accuracy, coat, filmTable, diagnostics
    Object.assign(this, handle.describe());
  }
  // Each curve: 3 values (R, G, B) per cosine mu in [0, 1], in one Float64Array.
  fresnel(mu) { return unwrapped(this.handle.fresnel(numbers(mu, "mu"))); }
  exact(mu) { return unwrapped(this.handle.exact(numbers(mu, "mu"))); }
  schlick(mu) { return unwrapped(this.handle.schlick(numbers(mu, "mu"))); }
  f82Tint(mu) { return unwrapped(this.handle.f82Tint(numbers(mu, "mu"))); }
  // A coated material's lobes: { base: 3 values per cosine, coat: 1 per cosine }.
  coatedFresnel(mu) { return unwrapped(this.handle.coatedFresnel(numbers(mu, "mu"))); }
  // The preintegrated F at pairs (NdotV, roughness): 3 values per pair.
  fbar(ndotv, roughness) {
    return unwrapped(this.handle.fbar(numbers(ndotv, "ndotv"), numbers(roughness, "roughness")));
  }
}

export class TextOutputs extends Handle {
  // "glsl" (GLSL 4.50 and GLSL ES 3.00 alike), "hlsl" or "wgsl".
  librarySource(language) { return unwrapped(this.handle.librarySource(checkedString(language, "language"))); }
  materialSource(language, compiled) {
    return unwrapped(this.handle.materialSource(checkedString(language, "language"), compiledHandle(compiled)));
  }
  materialJson(compiled) { return unwrapped(this.handle.materialJson(compiledHandle(compiled))); }
  // The build's basis: "auto" (a basis per material, a table of a layer per basis) or the one
  // basis every material is compiled against; the tables the library reads are of that basis.
  get basis() { return this.handle.basis(); }
}

function compiledHandle(compiled) {
  if (!(compiled instanceof CompiledMaterial)) throw new TypeError("compiled: a CompiledMaterial (from compile())");
  return compiled.handle;
}

export class Matc {
  #module;
  constructor(module) { this.#module = module; }

  get version() { return version; }
  // Whether parseMaterials reads MaterialX documents in this build.
  get readsMaterialX() { return this.#module.readsMaterialX(); }
  // The spectral presets: the measured metals matc ships ("Au", "Ag", ...).
  spectralPresets() { return this.#module.spectralPresets(); }

  // The materials of a material file's JSON, a MaterialX document (path ending in .mtlx) or a glTF
  // asset (.gltf, .glb): text or its bytes. `files`: the files it names (a spectral CSV, a .gltf's
  // buffers), { "name relative to its folder": text or bytes }; without it, such a file cannot be
  // read (the instance has no file system).
  parseMaterials(text, path = "material.json", { files } = {}) {
    const handles = unwrapped(this.#module.parseMaterials(checkedText(text, "text"), checkedString(path, "path"),
                                                          checkedFiles(files)));
    return handles.map((handle) => new Material(handle));
  }
  // One material from JSON (text or bytes) or a plain object written as a material file.
  parseMaterial(input, { path = "material.json" } = {}) {
    let text = input;
    if (typeof input === "object" && input !== null && !(input instanceof Uint8Array) &&
        !(input instanceof ArrayBuffer)) {
      try {
        text = JSON.stringify(input);
      } catch (error) {
        throw new TypeError(`input: not representable as JSON (${error.message})`);
      }
    }
    const materials = this.parseMaterials(checkedText(text, "input"), path);
    if (materials.length !== 1) {
      for (const material of materials) material.dispose();
      throw new MatcError({ kind: "argument", message: `${path}: ${materials.length} materials; parseMaterials reads them all` });
    }
    return materials[0];
  }
  // options: { basis, colorSpace, gamutMapping } by the CLI's names (--basis, ...).
  compile(material, options = {}) {
    if (!(material instanceof Material)) throw new TypeError("material: a Material (from parseMaterial())");
    const handle = unwrapped(this.#module.compile(material.handle, ...optionStrings(options)));
    return new CompiledMaterial(handle, material);
  }
  // A glTF asset (a .glb's bytes, or a .gltf whose buffers are data URIs or given in `files` as
  // parseMaterials takes them; `path` ends in .glb or .gltf) written back with each metal's
  // compiled coefficients in the vendor extension MATC_materials_fresnel, every other byte as it
  // was (`matc gltf`, docs/gltf.md): { bytes: Uint8Array, materials: CompiledMaterial[] (its
  // metals, in the asset's order) }.
  compileGltf(bytes, path = "asset.glb", options = {}, { files } = {}) {
    const result = unwrapped(this.#module.compileGltf(checkedText(bytes, "bytes"), checkedString(path, "path"),
                                                      ...optionStrings(options), checkedFiles(files)));
    return { bytes: result.bytes,
             materials: result.materials.map(({ material, compiled }) => new CompiledMaterial(compiled, new Material(material))) };
  }
  // The texts `matc` writes with the same options, byte for byte.
  textOutputs(options = {}) {
    return new TextOutputs(unwrapped(this.#module.textOutputs(...optionStrings(options))));
  }
}

// A new instance. In a page the binary is fetched beside this module (or from `locateFile`); in
// Node it is read from the package. `wasmBinary`: the binary's bytes, to skip both.
export async function createMatc({ wasmBinary, locateFile } = {}) {
  const wasmUrl = new URL("./matc.wasm", import.meta.url);
  if (!wasmBinary && !locateFile && wasmUrl.protocol === "file:") {
    const { readFile } = await import("node:fs/promises");
    wasmBinary = await readFile(wasmUrl);
  }
  const options = {};
  if (wasmBinary) options.wasmBinary = wasmBinary;
  if (locateFile) options.locateFile = locateFile;
  return new Matc(await createMatcModule(options));
}

export { tableFiles } from "./tables.mjs";
