// What the engine-against-reference tests share (check-three-reference.mjs,
// check-babylon-reference.mjs): the scene's materials compiled and their exact Fresnel curves
// tabulated, the textured inlay's maps and bake, the page run, the errors by region of the sphere,
// the checks, the comparison images and docs/web-engines.md's table, and the frame timing.
// Each engine gives a page (config -> HTML) that renders "<material> reference", "<material>
// stock", "<material> matc", "<material> matc-engine-ltc" and "<material> matc-quality" (the
// areaLights options; and "inlaid_metals baked") as base64 RGBA floats, the reference with
// 1 + NdotV in alpha. An engine with a glTF loader (engine.coated) also renders the coated car
// paint of examples/gltf as its own loader builds it ("Car_Paint stock") and as matc's loader
// does ("Car_Paint matc"), against the two-lobe reference.
//   runReferenceComparison(engine, process.argv.slice(2)), argv: MATC MATERIALS_DIR
//   EXAMPLES_WEB_DIR MATC_EXAMPLE_MAPS EXAMPLES_TEXTURED_DIR [--markdown] [--images DIR]
//   [--size N] [--lights environment|point|rect] [--timing]
// --markdown prints the table alone (the checks' lines go to stderr); --images writes the
// comparison panels as PNG; --lights keeps one light path; --timing adds frame times.
import { cpSync, mkdirSync, mkdtempSync, readFileSync, rmSync } from "node:fs";
import { tmpdir } from "node:os";
import { dirname, join } from "node:path";
import { kWebRoots, runPage } from "./browser-page.mjs";
import { kReferenceFragmentShader, kReferenceVertexShader, kScene, rectLightGeometry,
         sceneWith } from "./engine-scene.mjs";
import { displayByte, writePng } from "./png.mjs";
import { materialsOnSpheres } from "./gltf-assets.mjs";
import { check, finish } from "./report.mjs";
import { run } from "./shader-cases.mjs";

const kMaterials = ["figure2_edge_tint", "beryllium"];
// Regions of the sphere by NdotV, and what each must show. The silhouette's pixels sit where the
// split sum is poorest (and, in three.js, shade with a roughness the normal's derivative widened
// towards 1): there matc's material must be closer than the stock one. Grazing and middle angles
// are where Schlick's curve leaves the exact one: at most half the stock error. At the centre
// both have the exact F0, and what is left is the split sum's own error.
const kRegions = [
  { name: "silhouette (NdotV < 0.1)", test: (nv) => nv < 0.1, bound: 1.0, means: "closer than stock" },
  { name: "grazing (0.1-0.3)", test: (nv) => nv >= 0.1 && nv < 0.3, bound: 0.5, means: "at most half" },
  { name: "middle (0.3-0.7)", test: (nv) => nv >= 0.3 && nv < 0.7, bound: 0.5, means: "at most half" },
  { name: "centre (NdotV >= 0.7)", test: (nv) => nv >= 0.7, bound: 1.1,
    means: "the split sum's own error: no more than stock + 10%" },
];

// The renders of each material with useMatcFresnel's other areaLights options ("<material> <kind>").
const kAreaLightVariants = [{ kind: "matc-engine-ltc", label: "engine's LTC" },
                            { kind: "matc-quality", label: "quality level" }];

// The coated metal: the car paint of examples/gltf (a metallic base under a clear coat, read as
// docs/gltf.md reads it), each material of the asset on a sphere for the engines' loaders.
const kCoatedAsset = { source: join("gltf", "car_paint.gltf"), file: "car_paint.glb" };

// The reference's exact curves as its texture holds them: row 0 the metal's (a coated metal's
// base lobe's), row 1 a coated metal's coat lobe's (zero for a bare metal); RGBA per cosine.
function fresnelRows(base, coat = null) {
  return [...base.flatMap((rgb) => [...rgb, 1]), ...base.flatMap((_, i) => coat ? [coat[i], coat[i], coat[i], 1] : [0, 0, 0, 1])];
}

const floats = (text) => new Float32Array(Buffer.from(text, "base64").buffer.slice(0));

// Radiance-weighted error per region and channel: sum |x - reference| / sum reference.
function regionErrors(image, reference) {
  return kRegions.map((region) => {
    const difference = [0, 0, 0], total = [0, 0, 0];
    let pixels = 0;
    for (let i = 0; i < reference.length; i += 4) {
      if (reference[i + 3] === 0) continue;  // background
      const nv = reference[i + 3] - 1;
      if (!region.test(nv)) continue;
      pixels += 1;
      for (let c = 0; c < 3; ++c) {
        difference[c] += Math.abs(image[i + c] - reference[i + c]);
        total[c] += reference[i + c];
      }
    }
    const all = difference.reduce((a, b) => a + b) / total.reduce((a, b) => a + b);
    return { pixels, channels: difference.map((d, c) => d / total[c]), all };
  });
}

function writePanels(path, size, panels) {
  mkdirSync(dirname(path), { recursive: true });
  const rgb = new Uint8Array(size * panels.length * size * 3);
  panels.forEach(({ image, scaleBy, against }, p) => {
    for (let y = 0; y < size; ++y) {
      for (let x = 0; x < size; ++x) {
        const i = 4 * ((size - 1 - y) * size + x);  // render targets are bottom-up
        const o = 3 * (y * size * panels.length + p * size + x);
        for (let c = 0; c < 3; ++c) {
          rgb[o + c] = against
              ? Math.round(Math.min(1, Math.abs(image[i + c] - against[i + c]) * scaleBy) * 255)
              : displayByte(image[i + c]);
        }
      }
    }
  });
  writePng(path, size * panels.length, size, rgb);
}

// engine: { name (e.g. "three.js"), prefix (image file names), label (the table's first words),
// page(config) -> HTML, prepare(dir) -> extra served folders, runPage (more options for runPage:
// realTime, browserArgs) }.
export async function runReferenceComparison(engine, argv) {
  const [matc, materialsDir, webDir, exampleMaps, texturedDir, ...options] = argv;
  const markdown = options.includes("--markdown");
  const optionValue = (name) => options.includes(name) ? options[options.indexOf(name) + 1] : null;
  const imagesDir = optionValue("--images");
  const lightPaths = optionValue("--lights") ?? "all";
  const size = Number(optionValue("--size") ?? kScene.size);
  const print = console.log;
  if (markdown) console.log = (...args) => console.error(...args);
  const dir = mkdtempSync(join(tmpdir(), "matc-engine-reference-"));
  try {
    const out = join(dir, "out");
    // The coated asset: its materials on spheres, and the asset as `matc gltf` writes it (matc's
    // loader reads the extension; the two-lobe snippet comes from this build, which compiles it).
    const asset = join(dir, kCoatedAsset.file), assets = join(dir, "gltf");
    if (engine.coated) {
      mkdirSync(assets);
      await materialsOnSpheres(join(dirname(materialsDir), kCoatedAsset.source), asset);
      run(matc, ["gltf", "-q", asset, "-o", join(assets, kCoatedAsset.file)]);
    }
    run(matc, ["-q", "-o", out, "--emit", "glsl,wgsl,json,lut,ltc,coefficient-table", "--lut-precision", "f32",
               ...kMaterials.map((name) => join(materialsDir, `${name}.json`)), ...(engine.coated ? [asset] : [])]);
    const cosines = Array.from({ length: kScene.fresnelSamples }, (_, i) => i / (kScene.fresnelSamples - 1));
    const materials = kMaterials.map((name) => {
      const compiled = JSON.parse(readFileSync(join(out, `${name}.json`), "utf8"));
      const exact = JSON.parse(run(matc, ["eval", join(materialsDir, `${name}.json`), "--mu", cosines.join(",")]))
                      .F_exact;
      return { name, roughness: compiled.roughness, f0: compiled.coefficients.map((row) => row[0]),
               exactFresnel: fresnelRows(exact) };
    });
    // Each lobe's exact curve; the base's multiple scattering with its curve's F0.
    let coated = null;
    if (engine.coated) {
      const evaluated = JSON.parse(run(matc, ["eval", asset, "--mu", cosines.join(",")]));
      const compiled = JSON.parse(readFileSync(join(out, `${evaluated.name}.json`), "utf8"));
      coated = { name: evaluated.name, asset: `/gltf/${kCoatedAsset.file}`, roughness: compiled.roughness,
                 coatRoughness: evaluated.coat.roughness, f0: evaluated.F_exact_base.at(-1),
                 exactFresnel: fresnelRows(evaluated.F_exact_base, evaluated.F_exact_coat) };
    }
    // The inlay's maps and bake, as the examples' build makes them.
    const textured = join(dir, "textured");
    run(exampleMaps, ["--size", "512", "-o", join(textured, "maps")]);
    cpSync(join(texturedDir, "inlaid_metals.json"), join(textured, "inlaid_metals.json"));
    run(matc, ["bake", "-q", "--f0", "-o", join(textured, "baked"), join(textured, "inlaid_metals.json")]);
    const config = { textured: { name: "inlaid_metals", roughness: 0.3 }, scene: { ...sceneWith(lightPaths), size }, materials, coated,
                     rect: rectLightGeometry(kScene.rect), vertexShader: kReferenceVertexShader,
                     fragmentShader: kReferenceFragmentShader };
    const roots = { ...kWebRoots, web: webDir, out, textured, ...(coated ? { gltf: assets } : {}),
                    ...(engine.prepare?.(dir) ?? {}) };
    const pageOptions = { roots, dir, budgetMs: 600000, ...engine.runPage };
    const result = await runPage({ html: engine.page(config), ...pageOptions });
    check(result.errors.length === 0, `${engine.name}: ${result.errors.join("\n")}`);
    // The renders "<name> <kind>" of `kinds` (the reference first) as floats, or null where one is
    // missing (a failed check); with --images, their panels and each one's difference from the
    // reference (4x), <prefix>_<name>.png and <prefix>_<name>_difference.png.
    const rendered = (name, kinds) => {
      const texts = kinds.map((kind) => result.images[`${name} ${kind}`]);
      check(texts.every(Boolean), `${name}: not every image was rendered`);
      if (!texts.every(Boolean)) return null;
      const images = texts.map(floats);
      if (imagesDir) {
        const [reference, ...others] = images;
        writePanels(join(imagesDir, `${engine.prefix}_${name}.png`), size, images.map((image) => ({ image })));
        writePanels(join(imagesDir, `${engine.prefix}_${name}_difference.png`), size,
                    others.map((image) => ({ image, against: reference, scaleBy: 4 })));
      }
      return images;
    };
    const rows = [];
    for (const { name } of materials) {
      const images = rendered(name, ["reference", "stock", "matc"]);
      if (!images) continue;
      const [reference, stock, ours] = images;
      const stockErrors = regionErrors(stock, reference), oursErrors = regionErrors(ours, reference);
      kRegions.forEach((region, r) => {
        const s = stockErrors[r], o = oursErrors[r];
        check(o.pixels > 50, `${name}, ${region.name}: only ${o.pixels} pixels`);
        check(o.all <= region.bound * s.all, `${name}, ${region.name}: matc's error ${o.all.toFixed(4)} ` +
                                             `against the stock material's ${s.all.toFixed(4)}: not ${region.means}`);
        rows.push({ name, region: region.name, pixels: o.pixels, stock: s, ours: o });
      });
      // The other areaLights options: "engine" (the engine's LTC shape with matc's Fresnel) and
      // "quality" (matc's quality level): closer than stock.
      for (const { kind, label } of kAreaLightVariants) {
        const image = result.images[`${name} ${kind}`];
        check(Boolean(image), `${name}: the ${label} variant was not rendered`);
        if (!image) continue;
        regionErrors(floats(image), reference).forEach((o, r) => {
          const s = stockErrors[r];
          check(o.all <= Math.max(kRegions[r].bound, 1.0) * s.all,
                `${name} (${label}), ${kRegions[r].name}: matc's error ${o.all.toFixed(4)} against the stock ` +
                `material's ${s.all.toFixed(4)}`);
          rows.push({ name: `${name} (${label})`, region: kRegions[r].name, pixels: o.pixels, stock: s, ours: o });
        });
      }
    }
    // The inlay through the coefficient table and through its bake.
    const inlay = config.textured.name;
    const texturedImages = rendered(inlay, ["reference", "stock", "matc", "baked"]);
    if (texturedImages) {
      const [reference, stock, table, baked] = texturedImages;
      const stockErrors = regionErrors(stock, reference);
      for (const [label, image] of [["coefficient table", table], ["baked", baked]]) {
        regionErrors(image, reference).forEach((o, r) => {
          const s = stockErrors[r];
          // Closer than stock, and at the centre (both with the maps' F0) within its +10%.
          const bound = Math.max(kRegions[r].bound, 1.0);
          check(o.all <= bound * s.all, `${inlay} (${label}), ${kRegions[r].name}: matc's error ` +
                                        `${o.all.toFixed(4)} against the stock material's ${s.all.toFixed(4)}`);
          rows.push({ name: `${inlay} (${label})`, region: kRegions[r].name, pixels: o.pixels, stock: s, ours: o });
        });
      }
    }
    // The coated car paint as the engine's glTF loader builds it and as matc's does: closer to
    // the two-lobe reference than the engine's own in every region.
    const coatedImages = coated ? rendered(coated.name, ["reference", "stock", "matc"]) : null;
    if (coatedImages) {
      const [reference, stock, ours] = coatedImages;
      const stockErrors = regionErrors(stock, reference);
      regionErrors(ours, reference).forEach((o, r) => {
        const s = stockErrors[r];
        check(o.pixels > 50, `${coated.name}, ${kRegions[r].name}: only ${o.pixels} pixels`);
        check(o.all < s.all, `${coated.name} (glTF), ${kRegions[r].name}: matc's error ${o.all.toFixed(4)} ` +
                             `against the engine's loading's ${s.all.toFixed(4)}: not closer`);
        rows.push({ name: `${coated.name} (glTF, coated)`, region: kRegions[r].name, pixels: o.pixels, stock: s, ours: o });
      });
    }
    const percent = (x) => `${(100 * x).toFixed(1)}%`;
    const table = [
      `${engine.label}, ${size}x${size} pixels; ` +
      `reference: ${kScene.samples.environment} environment samples and ${kScene.samples.rectSide ** 2} ` +
      "rect-light samples per pixel. Radiance-weighted error against the reference, " +
      "sum |render - reference| / sum reference, per region of the sphere (all channels; R, G, B):",
      "",
      `| material | region | pixels | stock ${engine.name} | with matc | stock R, G, B | matc R, G, B |`,
      "|---|---|---:|---:|---:|---|---|",
      ...rows.map(({ name, region, pixels, stock, ours }) =>
        `| ${name} | ${region} | ${pixels} | ${percent(stock.all)} | ${percent(ours.all)} | ` +
        `${stock.channels.map(percent).join(", ")} | ${ours.channels.map(percent).join(", ")} |`),
    ];
    if (options.includes("--timing")) {
      // Frame times measured in the page, which runs in real time for them (virtual time has
      // no clock): per kind, the mean over its materials, the fastest of three runs.
      const frames = 100, runs = 3;
      const perFrame = {};
      for (const kind of ["stock", "matc", ...kAreaLightVariants.map((variant) => variant.kind)]) {
        const times = [];
        for (let run = 0; run < runs; ++run) {
          const timed = await runPage({ html: engine.page({ ...config, timing: { kind, frames } }), ...pageOptions,
                                        realTime: true });
          check(timed.errors.length === 0 && timed.frameTimes?.length > 0,
                `${engine.name}, timing ${kind}: ${timed.errors.join("\n") || "no frame timed"}`);
          const drawn = timed.frameTimes ?? [];
          times.push(drawn.reduce((a, b) => a + b, 0) / Math.max(drawn.length, 1));
        }
        perFrame[kind] = Math.min(...times);
      }
      table.push("", `Frame time of this ${size}x${size} frame on SwiftShader (Chromium's CPU rasteriser: ` +
                 "it shows the shaders' ALU and texture work, not a GPU's timing), timed in the page " +
                 `over ${frames} frames per material, the fastest of ${runs} runs: stock ${perFrame.stock.toFixed(1)} ms, ` +
                 `with matc ${perFrame.matc.toFixed(1)} ms, with matc and the engine's LTC shape for the ` +
                 `rect light ${perFrame["matc-engine-ltc"].toFixed(1)} ms, with matc at the quality level ` +
                 `${perFrame["matc-quality"].toFixed(1)} ms.`);
    }
    if (markdown) print(table.join("\n"));
    else console.log(table.join("\n"));
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
  finish();
}
