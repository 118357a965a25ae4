// Types of the matc package (index.mjs; docs/web.md).

export declare const version: string;

export interface Diagnostic {
  severity: "error" | "warning" | "note";
  path: string;
  /** 1-based; 0: the whole input. */
  line: number;
  column: number;
  field: string;
  message: string;
  allowed: string;
  /** The line the CLI prints: "path:line:col: error: field: message; allowed". */
  text: string;
}

export declare class MatcError extends Error {
  kind: "material" | "argument" | "memory" | "internal";
  diagnostics: Diagnostic[];
}

export interface CompileOptions {
  /** --basis: "auto" (default: each material the basis that holds its curve), or one basis for
   *  every material: "powers", "extended", "paper" or "f82". */
  basis?: string;
  /** --color-space, e.g. "lin_rec709" (default) or "acescg". */
  colorSpace?: string;
  /** --gamut-mapping: "none" (default) or "desaturate". */
  gamutMapping?: string;
}

/** Numbers in: a number, an array or a typed array of numbers. */
export type Numbers = number | ArrayLike<number> | Float64Array | Float32Array;
/** Coefficient rows R, G, B of c_0..c_3. */
export type CoefficientRows = [Float64Array, Float64Array, Float64Array];

declare class Disposable {
  /** Frees the native object now rather than when it is garbage-collected. */
  dispose(): void;
}

export declare class Material extends Disposable {
  readonly name: string;
  readonly model: "artistic" | "ior" | "spectral" | "f82_tint";
  readonly path: string;
  /** Its material file's JSON. */
  readonly json: string;
  readonly coated: boolean;
  readonly diagnostics: Diagnostic[];
}

export interface Accuracy {
  samples: number;
  maxError: Float64Array;
  rmsError: Float64Array;
  schlickMaxError: Float64Array;
  schlickRmsError: Float64Array;
  f82TintMaxError: Float64Array;
  f82TintRmsError: Float64Array;
}

export interface Coat {
  weight: number;
  ior: number;
  roughness: number;
  color: Float64Array;
  underCoatCoefficients: CoefficientRows;
  coatCoefficients: Float64Array;
  layeredMaxError: Float64Array;
}

/** A filmed metal's own table (docs/thin-film.md): width x height RGBA texels, row after row, as
 *  <name>.film.<ext> holds them at f32; row 0 F over sqrt(mu), rows 1-17 Fbar. */
export interface FilmTable {
  width: number;
  height: number;
  texels: Float32Array;
}

export declare class CompiledMaterial extends Disposable {
  readonly material: Material;
  readonly name: string;
  readonly basis: string;
  readonly coefficients: CoefficientRows;
  readonly f0: Float64Array;
  readonly f82: Float64Array;
  readonly accuracy: Accuracy;
  readonly coat: Coat | null;
  /** A filmed metal's table, which its shaders sample for F and Fbar; null without a film. */
  readonly filmTable: FilmTable | null;
  readonly diagnostics: Diagnostic[];
  /** F as the shaders compute it: 3 values (R, G, B) per cosine in [0, 1]. */
  fresnel(mu: Numbers): Float64Array;
  exact(mu: Numbers): Float64Array;
  schlick(mu: Numbers): Float64Array;
  f82Tint(mu: Numbers): Float64Array;
  coatedFresnel(mu: Numbers): { base: Float64Array; coat: Float64Array };
  /** The preintegrated F at pairs (NdotV, roughness): 3 values per pair. */
  fbar(ndotv: Numbers, roughness: Numbers): Float64Array;
}

export type ShaderLanguage = "glsl" | "hlsl" | "wgsl";

export declare class TextOutputs extends Disposable {
  librarySource(language: ShaderLanguage): string;
  materialSource(language: ShaderLanguage, compiled: CompiledMaterial): string;
  materialJson(compiled: CompiledMaterial): string;
  /** "auto" (a basis per material: the library reads a table of a layer per basis) or the one
   *  basis every material is compiled against. */
  readonly basis: string;
}

export declare class Matc {
  readonly version: string;
  /** True in every build: the package reads MaterialX documents (with rapidxml). */
  readonly readsMaterialX: boolean;
  spectralPresets(): string[];
  /** A material file's JSON, a MaterialX document (path ending in .mtlx) or a glTF asset (.gltf
   *  or .glb, its metals; a .glb as bytes; external buffers cannot be read here), as text or bytes. */
  /** `files`: the files the input names (a spectral CSV, a .gltf's buffers), by their paths relative to its folder. */
  parseMaterials(text: string | Uint8Array | ArrayBuffer, path?: string,
                 options?: { files?: Record<string, string | Uint8Array | ArrayBuffer> }): Material[];
  parseMaterial(input: string | Uint8Array | ArrayBuffer | object, options?: { path?: string }): Material;
  compile(material: Material, options?: CompileOptions): CompiledMaterial;
  /**
   * A glTF asset (a .glb, or a .gltf whose buffers are data URIs; `path` ends in .glb or .gltf)
   * written back with each metal's compiled coefficients in MATC_materials_fresnel, every other
   * byte as it was (`matc gltf`, docs/gltf.md).
   */
  compileGltf(bytes: Uint8Array | ArrayBuffer | string, path?: string, options?: CompileOptions,
              input?: { files?: Record<string, string | Uint8Array | ArrayBuffer> }):
    { bytes: Uint8Array; materials: CompiledMaterial[] };
  textOutputs(options?: CompileOptions): TextOutputs;
}

export declare function createMatc(options?: {
  wasmBinary?: ArrayBuffer | Uint8Array;
  locateFile?: (path: string, prefix: string) => string;
}): Promise<Matc>;

export interface TableUrls { lut: string; coefficientTable: string; ltc: string }
export declare const tableFiles: { ktx2: TableUrls; raw: TableUrls };
