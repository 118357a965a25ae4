// glTF assets as artists make them, built with glTF-Transform (npm @gltf-transform/core and
// extensions) for the glTF checks (check-gltf-assets.mjs, check-three-gltf.mjs).
import { writeFileSync } from "node:fs";
import { join } from "node:path";
import { Document, NodeIO } from "@gltf-transform/core";
import { KHRMaterialsClearcoat, KHRMaterialsIridescence, KHRMaterialsSpecular } from "@gltf-transform/extensions";
import { pngBytes } from "./png.mjs";

// A UV sphere's positions, normals, texture coordinates and indices.
function sphere(document, buffer, segments = 16, rings = 8) {
  const positions = [], normals = [], uvs = [], indices = [];
  for (let r = 0; r <= rings; ++r) {
    for (let s = 0; s <= segments; ++s) {
      const theta = (Math.PI * r) / rings, phi = (2 * Math.PI * s) / segments;
      const n = [Math.sin(theta) * Math.cos(phi), Math.cos(theta), Math.sin(theta) * Math.sin(phi)];
      positions.push(...n);
      normals.push(...n);
      uvs.push(s / segments, r / rings);
    }
  }
  for (let r = 0; r < rings; ++r) {
    for (let s = 0; s < segments; ++s) {
      const a = r * (segments + 1) + s, b = a + segments + 1;
      indices.push(a, b, a + 1, b, b + 1, a + 1);
    }
  }
  const accessor = (type, array) => document.createAccessor().setType(type).setArray(array).setBuffer(buffer);
  return document.createPrimitive()
    .setAttribute("POSITION", accessor("VEC3", new Float32Array(positions)))
    .setAttribute("NORMAL", accessor("VEC3", new Float32Array(normals)))
    .setAttribute("TEXCOORD_0", accessor("VEC2", new Float32Array(uvs)))
    .setIndices(accessor("SCALAR", new Uint16Array(indices)));
}

// One UV sphere per material in a row along x; `segments` and `rings` as sphere() takes them.
function scene(document, materials, { segments = 16, rings = 8 } = {}) {
  const buffer = document.createBuffer("geometry");
  const root = document.createScene("scene");
  materials.forEach((material, i) => {
    const mesh = document.createMesh(material.getName())
      .addPrimitive(sphere(document, buffer, segments, rings).setMaterial(material));
    root.addChild(document.createNode(material.getName()).setMesh(mesh).setTranslation([2.5 * i, 0, 0]));
  });
}

// F0 = (i / 32)^4 for i = 30, 28, 16: entries of a textured metal's F0 table (docs/gltf.md),
// exact in binary, where the table holds the metal compiled at that F0.
const kF0TableEntry = { 30: 0.7724761962890625, 28: 0.586181640625, 16: 0.0625 };

// Texels that every sRGB decoding maps to 1, 0, 1: a base colour texture that makes the engine's
// base colour the factor with green 0.
const magentaTexture = (document, name) => document.createTexture(name)
  .setImage(pngBytes(4, 4, new Uint8Array(4 * 4 * 3).map((_, i) => (i % 3 === 1 ? 0 : 255)))).setMimeType("image/png");

// car.glb: the car-paint asset (options: the metals' roughness; an iridescent foil metal too, and
// `airFoil`: one under a film of index 1, which shows nothing and compiles bare; `lacqueredFoil`: a foil
// under a clear coat, the film between coat and metal; a textured bare trim; perPixel: the paint's texture (255, 0, 255) with red and blue of its factor on
// F0-table entries, under a partial coat (0.7: the metal in air shows through too), and an
// edge-coloured textured trim likewise, so that a loader following
// them per pixel shades them as the metals compiled at F0 = factor with green 0).
export async function carAsset(path, { paintRoughness = 0.4, chromeRoughness = 0.08, foil = false, airFoil = false,
                                       lacqueredFoil = false, trim = false, perPixel = false } = {}) {
  const document = new Document();
  const clearcoat = document.createExtension(KHRMaterialsClearcoat);
  const flakes = new Uint8Array(8 * 8 * 3).map((_, i) => (i % 3 === 0 ? 200 : 40) + (i % 7));
  const texture = perPixel ? magentaTexture(document, "paint")
                           : document.createTexture("paint").setImage(pngBytes(8, 8, flakes)).setMimeType("image/png");
  const paint = document.createMaterial("Car Paint")
    .setBaseColorFactor(perPixel ? [kF0TableEntry[28], 0.06, kF0TableEntry[16], 1] : [0.55, 0.06, 0.05, 1])
    .setMetallicFactor(1).setRoughnessFactor(paintRoughness).setBaseColorTexture(texture)
    .setExtension("KHR_materials_clearcoat", clearcoat.createClearcoat().setClearcoatFactor(perPixel ? 0.7 : 1)
      .setClearcoatRoughnessFactor(0.03));
  const chrome = document.createMaterial("Chrome").setBaseColorFactor([0.55, 0.556, 0.554, 1])
    .setMetallicFactor(1).setRoughnessFactor(chromeRoughness);
  const tyre = document.createMaterial("Tyre").setBaseColorFactor([0.02, 0.02, 0.02, 1])
    .setMetallicFactor(0).setRoughnessFactor(0.9);
  const materials = [paint, chrome, tyre];
  const iridescence = (foil || airFoil || lacqueredFoil) && document.createExtension(KHRMaterialsIridescence);
  if (foil) {
    materials.push(document.createMaterial("Foil").setBaseColorFactor([0.9, 0.9, 0.9, 1]).setMetallicFactor(1)
      .setRoughnessFactor(0.3).setExtension("KHR_materials_iridescence", iridescence.createIridescence().setIridescenceFactor(1)));
  }
  if (airFoil) {
    materials.push(document.createMaterial("Air Foil").setBaseColorFactor([0.9, 0.9, 0.9, 1]).setMetallicFactor(1)
      .setRoughnessFactor(0.3).setExtension("KHR_materials_iridescence",
                                            iridescence.createIridescence().setIridescenceFactor(1).setIridescenceIOR(1)));
  }
  if (lacqueredFoil) {
    materials.push(document.createMaterial("Lacquered Foil").setBaseColorFactor([0.9, 0.9, 0.9, 1]).setMetallicFactor(1)
      .setRoughnessFactor(0.3).setExtension("KHR_materials_iridescence", iridescence.createIridescence().setIridescenceFactor(1))
      .setExtension("KHR_materials_clearcoat", clearcoat.createClearcoat().setClearcoatFactor(1)
        .setClearcoatRoughnessFactor(0.1)));
  }
  if (trim) {
    // A textured bare metal: every texel (255, 0, 255), exact in any sRGB decoding, so the
    // engine's base colour is the factor with green 0: F0 (0.9, 0, 0.6) per pixel.
    materials.push(document.createMaterial("Trim").setBaseColorFactor([0.9, 0.8, 0.6, 1]).setMetallicFactor(1)
      .setRoughnessFactor(0.3).setBaseColorTexture(magentaTexture(document, "trim")));
  }
  if (perPixel) {
    const specular = document.createExtension(KHRMaterialsSpecular);
    // The edge colour is the draft EXT_materials_specular_edge_color inside KHR_materials_specular,
    // which glTF-Transform does not know: added to the GLB's JSON below.
    materials.push(document.createMaterial("Edge Trim").setBaseColorFactor([kF0TableEntry[30], 0.7, kF0TableEntry[28], 1])
      .setMetallicFactor(1).setRoughnessFactor(0.3).setBaseColorTexture(magentaTexture(document, "edge trim"))
      .setExtension("KHR_materials_specular", specular.createSpecular().setSpecularColorFactor([0.9, 0.75, 0.6])));
  }
  scene(document, materials);
  let bytes = await new NodeIO().registerExtensions([KHRMaterialsClearcoat, KHRMaterialsIridescence, KHRMaterialsSpecular])
    .writeBinary(document);
  if (perPixel) {
    bytes = withGlbJson(bytes, (json) => {
      const edgeTrim = json.materials.find((material) => material.name === "Edge Trim");
      edgeTrim.extensions.KHR_materials_specular.extensions =
        { EXT_materials_specular_edge_color: { specularEdgeColorEnabled: true } };
      json.extensionsUsed.push("EXT_materials_specular_edge_color");
    });
  }
  writeFileSync(path, bytes);
}

// The metals of metalRoughAsset: the same base colour and roughness, metalness from a texture's
// blue channel (every texel alike: 0, 128 and 255 of 255, read as linear data) or a factor.
export const kMetalRough = {
  baseColor: [0.9, 0.6, 0.3], roughness: 0.3,
  textured: { "Metal 0": 0, "Metal Half": 128, "Metal Full": 255 },
  factor: { "Metal Factor": 0.3 }, plain: "Metal Plain",
  coat: { factor: 0.8, roughness: 0.1 },  // metal_rough_coated.glb's
  edge: [0.95, 0.8, 0.6],                 // metal_rough_edge.glb's edge colour
};

// metal_rough.glb: glTF's metal-rough model as artists paint it, one material per metalness:
// a metallicRoughnessTexture (green 255: roughness at its factor; blue the metalness) on the
// textured ones, a metallicFactor of 0.3 on one, and a plain full metal (factor 1, no texture).
// `coat`: every material under a KHR_materials_clearcoat ({ factor, roughness }); `edge`: every
// material's edge colour (KHR_materials_specular's specularColorFactor with
// EXT_materials_specular_edge_color: an F82 tint, Babylon.js's OpenPBR conductor model).
export async function metalRoughAsset(path, { baseColor = kMetalRough.baseColor, coat = null, edge = null } = {}) {
  const document = new Document();
  const clearcoat = coat && document.createExtension(KHRMaterialsClearcoat);
  const specular = edge && document.createExtension(KHRMaterialsSpecular);
  const material = (name) => {
    const made = document.createMaterial(name).setBaseColorFactor([...baseColor, 1])
      .setRoughnessFactor(kMetalRough.roughness).setMetallicFactor(1);
    if (edge) made.setExtension("KHR_materials_specular", specular.createSpecular().setSpecularColorFactor(edge));
    if (!coat) return made;
    return made.setExtension("KHR_materials_clearcoat", clearcoat.createClearcoat().setClearcoatFactor(coat.factor)
      .setClearcoatRoughnessFactor(coat.roughness));
  };
  const materials = Object.entries(kMetalRough.textured).map(([name, blue]) => material(name).setMetallicRoughnessTexture(
    document.createTexture(name).setMimeType("image/png")
      .setImage(pngBytes(4, 4, new Uint8Array(4 * 4 * 3).map((_, i) => [0, 255, blue][i % 3])))));
  for (const [name, factor] of Object.entries(kMetalRough.factor)) materials.push(material(name).setMetallicFactor(factor));
  materials.push(material(kMetalRough.plain));
  scene(document, materials);
  const bytes = await new NodeIO().registerExtensions([KHRMaterialsClearcoat, KHRMaterialsSpecular]).writeBinary(document);
  writeFileSync(path, !edge ? bytes : withGlbJson(bytes, (json) => {
    for (const written of json.materials) {
      written.extensions.KHR_materials_specular.extensions = { EXT_materials_specular_edge_color: { specularEdgeColorEnabled: true } };
    }
    json.extensionsUsed.push("EXT_materials_specular_edge_color");
  }));
}

// metalness_stripes.glb: one gold sphere whose metallicRoughnessTexture paints bands of metal,
// half metal and non-metal (blue 255, 0, 128, 0) from pole to pole, as a real asset paints worn paint or
// inlays: the look-development page's asset view in docs (docs/images/lookdev_asset.png).
export async function metalnessStripesAsset(path) {
  const document = new Document();
  const size = 64, bands = [255, 0, 128, 0];
  const texels = new Uint8Array(size * size * 3);
  for (let y = 0; y < size; ++y) {
    for (let x = 0; x < size; ++x) texels.set([0, 255, bands[Math.floor((y * 2 * bands.length) / size) % bands.length]], 3 * (y * size + x));
  }
  const gold = document.createMaterial("Inlaid gold").setBaseColorFactor([1.0, 0.71, 0.29, 1])
    .setRoughnessFactor(0.12).setMetallicFactor(1)
    .setMetallicRoughnessTexture(document.createTexture("stripes").setMimeType("image/png").setImage(pngBytes(size, size, texels)));
  scene(document, [gold], { segments: 96, rings: 48 });
  writeFileSync(path, await new NodeIO().writeBinary(document));
}

// A GLB (`bytes`) with its JSON chunk edited by `edit(json)`; the BIN chunk carried as it is.
function withGlbJson(bytes, edit) {
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  const jsonLength = view.getUint32(12, true);
  const json = JSON.parse(new TextDecoder().decode(bytes.subarray(20, 20 + jsonLength)));
  edit(json);
  const unpadded = new TextEncoder().encode(JSON.stringify(json));
  const jsonBytes = new Uint8Array(Math.ceil(unpadded.length / 4) * 4).fill(0x20);  // 4-byte aligned, space-padded
  jsonBytes.set(unpadded);
  const rest = bytes.subarray(20 + jsonLength);
  const glb = new Uint8Array(20 + jsonBytes.length + rest.length);
  const out = new DataView(glb.buffer);
  glb.set(bytes.subarray(0, 12));
  out.setUint32(8, glb.length, true);
  out.setUint32(12, jsonBytes.length, true);
  out.setUint32(16, 0x4e4f534a, true);  // "JSON"
  glb.set(jsonBytes, 20);
  glb.set(rest, 20 + jsonBytes.length);
  return glb;
}

// trim.gltf: JSON with its resources beside it, the draft extensions added to the JSON.
export async function trimAsset(dir) {
  const document = new Document();
  const specular = document.createExtension(KHRMaterialsSpecular);
  const clearcoat = document.createExtension(KHRMaterialsClearcoat);
  const chrome = document.createMaterial("EdgeChrome").setBaseColorFactor([0.55, 0.556, 0.554, 1])
    .setMetallicFactor(1).setRoughnessFactor(0.1)
    .setExtension("KHR_materials_specular", specular.createSpecular().setSpecularColorFactor([0.65, 0.68, 0.74]));
  const copper = document.createMaterial("LacqueredCopper").setBaseColorFactor([0.93, 0.62, 0.52, 1])
    .setMetallicFactor(1).setRoughnessFactor(0.3)
    .setExtension("KHR_materials_clearcoat", clearcoat.createClearcoat().setClearcoatFactor(0.8).setClearcoatRoughnessFactor(0.1));
  scene(document, [chrome, copper]);
  const { json, resources } = await new NodeIO().registerExtensions([KHRMaterialsSpecular, KHRMaterialsClearcoat])
    .writeJSON(document, { basename: "trim" });
  json.materials[0].extensions.KHR_materials_specular.extensions =
    { EXT_materials_specular_edge_color: { specularEdgeColorEnabled: true } };
  json.materials[1].extensions.KHR_materials_clearcoat.extensions = { KHR_materials_clearcoat_ior: { clearcoatIor: 1.6 } };
  json.extensionsUsed.push("EXT_materials_specular_edge_color", "KHR_materials_clearcoat_ior");
  writeFileSync(join(dir, "trim.gltf"), JSON.stringify(json, null, 2));
  for (const [name, bytes] of Object.entries(resources)) writeFileSync(join(dir, name), bytes);
}



// The materials of `source` (a glTF of materials alone, as examples/gltf holds them), each on a
// sphere, as a GLB at `path`: what an engine's loader needs to build them, their JSON as it was.
export async function materialsOnSpheres(source, path) {
  const io = new NodeIO().registerExtensions([KHRMaterialsClearcoat, KHRMaterialsIridescence, KHRMaterialsSpecular]);
  const document = await io.read(source);
  scene(document, document.getRoot().listMaterials());
  writeFileSync(path, await io.writeBinary(document));
}
