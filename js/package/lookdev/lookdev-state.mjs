// The look-development page's state: the material file's JSON (what the controls edit, what the
// page compiles and exports), the working colour space and the view mode; its colour conversions
// (colour pickers hold sRGB-encoded 8-bit colours, material files linear values) and its URL form
// (#material=<JSON>&space=<name>&view=<mode>), so that a link reproduces the material.

export const kModels = ["spectral", "artistic", "ior", "f82_tint"];
export const kViewModes = ["split", "matc", "engine"];

export const defaultState = () => ({
  material: { name: "Cu", spectral: { preset: "Cu" }, roughness: 0.3 },
  colorSpace: "lin_rec709",
  view: "split",
});

// A colour picker's "#rrggbb" (sRGB-encoded) as linear values, rounded to 4 decimals (8 bits carry
// less than that), and back.
const decode = (v) => (v <= 0.04045 ? v / 12.92 : ((v + 0.055) / 1.055) ** 2.4);
const encode = (v) => (v <= 0.0031308 ? v * 12.92 : 1.055 * v ** (1 / 2.4) - 0.055);
export function hexToLinear(hex) {
  const channels = [1, 3, 5].map((i) => parseInt(hex.slice(i, i + 2), 16) / 255);
  return channels.map((v) => Math.round(decode(v) * 1e4) / 1e4);
}
export function linearToHex(rgb) {
  const channels = rgbOf(rgb).map((v) => Math.round(encode(Math.min(Math.max(v, 0), 1)) * 255));
  return `#${channels.map((v) => v.toString(16).padStart(2, "0")).join("")}`;
}
// A material file's RGB value: a number (grey) or three numbers.
export const rgbOf = (value) => (Array.isArray(value) ? value.slice(0, 3) : [value, value, value]);

// The material's model: the one of kModels it has (a material file has exactly one).
export const modelOf = (material) => kModels.find((model) => model in material) ?? "spectral";

// The material with its keys in the order matc's files use (name, model, roughness, colour space,
// coat, film), the others kept after them.
export function ordered(material) {
  const out = { name: material.name };
  if (material.description !== undefined) out.description = material.description;
  const model = modelOf(material);
  out[model] = material[model];
  for (const key of ["roughness", "color_space", "coat", "film"]) {
    if (material[key] !== undefined) out[key] = material[key];
  }
  for (const [key, value] of Object.entries(material)) {
    if (!(key in out) && key !== "$schema" && !kModels.includes(key)) out[key] = value;
  }
  return out;
}

// The material file's text as the page exports it (and compiles it: diagnostics' lines and columns
// point into this text).
export const materialText = (material) => `${JSON.stringify(ordered(material), null, 2)}\n`;

// The state in a URL fragment, and back (null where the fragment holds no material; a material the
// compiler refuses is shown refused, as a pasted one is).
export function stateToHash({ material, colorSpace, view }) {
  const parameters = new URLSearchParams({ material: JSON.stringify(ordered(material)), space: colorSpace, view });
  return `#${parameters.toString()}`;
}

export function stateFromHash(hash) {
  const parameters = new URLSearchParams(hash.replace(/^#/, ""));
  const text = parameters.get("material");
  if (text === null) return null;
  let material;
  try {
    material = JSON.parse(text);
  } catch {
    return { error: "the link's material is not JSON" };
  }
  if (material === null || typeof material !== "object" || Array.isArray(material)) {
    return { error: "the link's material is not a JSON object" };
  }
  const defaults = defaultState();
  const view = parameters.get("view");
  return { material, colorSpace: parameters.get("space") ?? defaults.colorSpace,
           view: kViewModes.includes(view) ? view : defaults.view };
}

// Values a model starts from when the model control switches to it, close to the metal on screen
// (f0: its reflectance at normal incidence, linear RGB).
export function modelDefaults(model, f0) {
  const clamped = f0.map((v) => Math.round(Math.min(Math.max(v, 0), 0.99) * 1e4) / 1e4);
  switch (model) {
    case "artistic": return { reflectivity: clamped, edge_tint: clamped };
    case "ior": return { n: [0.27, 0.68, 1.32], k: [3.61, 2.62, 2.29] };  // a coppery starting point
    case "f82_tint": return { f0: clamped, tint: [1, 1, 1] };
    default: return { preset: "Cu" };
  }
}

// A material file's film block with the defaults matc compiles it with (docs/material-format.md:
// coverage 1, index 1.4, OpenPBR's), or null without one.
export function filmOf(material) {
  const film = material?.film;
  if (!film || typeof film !== "object") return null;
  return { weight: film.weight ?? 1, ior: film.ior ?? 1.4, thickness: film.thickness ?? 0 };
}

// The film a person switches on: anodic titanium's blue (index 2.4, 45 nm).
export const kNewFilm = { ior: 2.4, thickness: 45 };
