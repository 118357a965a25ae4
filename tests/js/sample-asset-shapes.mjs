// The material side of public glTF sample assets (Khronos glTF-Sample-Assets), as they arrive: each
// asset's materials (names, factors, which textures they bind, their extensions), its buffers
// (URI and byte length) and images (URI), read from the published .gltf files. Geometry is left
// out; buffers and images are written as placeholders of the same names (buffers of the same
// length, images as small PNG files), which is all matc reads of them.
// check-sample-assets.mjs runs them through matc.
import { writeFileSync } from "node:fs";
import { join } from "node:path";
import { pngBytes } from "./png.mjs";

// FlightHelmet (CC0): every material a metallic-roughness texture and no factor (metalness 1 times
// the texture): leather, rubber and glass painted as non-metal texels; the lenses transmissive.
const kHelmetParts = ["RubberWood", "GlassPlastic", "MetalParts", "LeatherParts", "Lenses"];
const flightHelmet = {
  name: "FlightHelmet",
  buffers: [["FlightHelmet.bin", 3227148]],
  images: kHelmetParts.flatMap((part) => ["Normal", "OcclusionRoughMetal", "BaseColor"]
    .map((map) => `FlightHelmet_Materials_${part}Mat_${map}.png`)),
  // HoseMat shares RubberWoodMat's textures (images 0 to 2).
  materials: [["HoseMat", 0], ["RubberWoodMat", 0], ["GlassPlasticMat", 3], ["MetalPartsMat", 6],
              ["LeatherPartsMat", 9], ["LensesMat", 12]].map(([name, first]) => ({
    name,
    pbrMetallicRoughness: { baseColorTexture: { index: first + 2 }, metallicRoughnessTexture: { index: first + 1 } },
    normalTexture: { index: first }, occlusionTexture: { index: first + 1 },
    ...(name === "LensesMat" ? { extensions: { KHR_materials_transmission: { transmissionFactor: 1 } } } : {}),
  })),
  extensionsUsed: ["KHR_materials_transmission"],
  metals: 6,
};

// CompareMetallic (CC0): the same logo as a dielectric (metallicFactor 0) and as a metal whose
// metalness is a texture.
const compareMetallic = {
  name: "CompareMetallic",
  buffers: [["CompareMetallic.bin", 58432]],
  images: ["Compare_Metallic_img0.jpg", "Compare_Metallic_img1.jpg"],
  materials: [
    { name: "glTF Logo", pbrMetallicRoughness: { baseColorTexture: { index: 0 }, metallicFactor: 0, roughnessFactor: 0.1 } },
    { name: "glTF Logo Metallic",
      pbrMetallicRoughness: { baseColorTexture: { index: 0 }, metallicRoughnessTexture: { index: 1 }, roughnessFactor: 0.1 } },
  ],
  metals: 1,
};

// ClearCoatCarPaint (CC0): a partly metallic paint (metallicFactor 0.3) under a clear coat, its
// normal map transformed (KHR_texture_transform, required).
const clearCoatCarPaint = {
  name: "ClearCoatCarPaint",
  buffers: [["ClearCoatCarPaint.bin", 73728]],
  images: ["ClearCoatCarPaint_Normal.png"],
  materials: [{
    name: "Clear Coat Car Paint",
    pbrMetallicRoughness: { baseColorFactor: [0.7, 0, 0, 1], metallicFactor: 0.3, roughnessFactor: 0.4 },
    normalTexture: { index: 0, scale: 0.2, extensions: { KHR_texture_transform: { scale: [3, 3] } } },
    extensions: { KHR_materials_clearcoat: { clearcoatFactor: 1, clearcoatRoughnessFactor: 0 } },
    doubleSided: false,
  }],
  extensionsUsed: ["KHR_texture_transform", "KHR_materials_clearcoat"],
  extensionsRequired: ["KHR_texture_transform", "KHR_materials_clearcoat"],
  metals: 1,
};

// IridescenceMetallicSpheres (CC-BY 4.0): 343 unnamed metals under KHR_materials_iridescence, a
// film over every grey base colour from 0 to 1 (sixths; the last the default factor, 1), index 1 to
// 2 and thickness 100 to 700 nm, in the published order (thickness, then colour, then index); and
// a textured, blended non-metal for the guides.
const kSphereColours = [0, 1 / 6, 1 / 3, 1 / 2, 2 / 3, 5 / 6, null];
const kSphereFilmIndices = [1, 1.17, 1.33, 1.5, 1.67, 1.83, 2];
const iridescenceMetallicSpheres = {
  name: "IridescenceMetallicSpheres",
  buffers: [["IridescenceMetallicSpheres.bin", 41756]],
  images: ["guides.png"],
  materials: [
    ...[100, 200, 300, 400, 500, 600, 700].flatMap((thickness) => kSphereColours.flatMap((colour) =>
      kSphereFilmIndices.map((ior) => ({
        pbrMetallicRoughness: { ...(colour === null ? {} : { baseColorFactor: [colour, colour, colour, 1] }), roughnessFactor: 0.1 },
        extensions: { KHR_materials_iridescence: { iridescenceFactor: 1, iridescenceIor: ior, iridescenceThicknessMaximum: thickness } },
      })))),
    { name: "Guides Material", alphaMode: "BLEND", doubleSided: true,
      pbrMetallicRoughness: { roughnessFactor: 0.5, metallicFactor: 0, baseColorTexture: { index: 0 } } },
  ],
  extensionsUsed: ["KHR_materials_ior", "KHR_materials_iridescence"],
  metals: 343,
};

export const kSampleAssetShapes = [flightHelmet, compareMetallic, clearCoatCarPaint, iridescenceMetallicSpheres];

// Writes `shape` into `dir` as <name>.gltf with its placeholder buffers and images; returns the
// asset's path.
export function writeSampleAsset(shape, dir) {
  const json = {
    asset: { version: "2.0", generator: "matc tests: the materials of a public sample asset, placeholders beside" },
    ...(shape.extensionsUsed ? { extensionsUsed: shape.extensionsUsed } : {}),
    ...(shape.extensionsRequired ? { extensionsRequired: shape.extensionsRequired } : {}),
    buffers: shape.buffers.map(([uri, byteLength]) => ({ uri, byteLength })),
    images: shape.images.map((uri) => ({ uri })),
    samplers: [{ magFilter: 9729, minFilter: 9987 }],
    textures: shape.images.map((_, source) => ({ sampler: 0, source })),
    materials: shape.materials,
  };
  for (const [uri, byteLength] of shape.buffers) writeFileSync(join(dir, uri), new Uint8Array(byteLength));
  // Every image a small PNG, JPEG-named ones too: the validator's findings on placeholders are the
  // input's, and must stay the output's.
  for (const uri of shape.images) writeFileSync(join(dir, uri), pngBytes(4, 4, new Uint8Array(4 * 4 * 3).fill(128)));
  const path = join(dir, `${shape.name}.gltf`);
  writeFileSync(path, JSON.stringify(json, null, 2));
  return path;
}
