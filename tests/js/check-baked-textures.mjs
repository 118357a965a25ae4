// Reads the coefficient textures `matc bake` writes with independent readers: ktx-parse for KTX2,
// parse-dds for DDS (f32: RGBA32F, which parse-dds decodes with its mipmaps). Both must describe
// an RGBA float texture with a full mip chain of the maps' size, and hold the same texels.
//   node check-baked-textures.mjs MATC_BINARY EXAMPLE_MAPS_BINARY
import { spawnSync } from "node:child_process";
import { mkdtempSync, readFileSync, rmSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { read as readKtx2 } from "ktx-parse";
import parseDds from "parse-dds";
import { check, finish } from "./report.mjs";

const [matc, makeMaps] = process.argv.slice(2);
const dir = mkdtempSync(join(tmpdir(), "matc-bake-"));
const size = 64;
const levels = 7;  // 64, 32, ..., 1

function run(command, args) {
  const result = spawnSync(command, args, { encoding: "utf8" });
  if (result.status !== 0) throw new Error(`${command} failed: ${result.stderr}`);
}

function bake(format, precision) {
  const out = join(dir, `${format}_${precision}`);
  run(matc, ["bake", "-q", "--reflectivity", join(dir, "inlaid_metals_r.png"), "--edge-tint",
             join(dir, "inlaid_metals_g.png"), "--name", "inlay", "--format", format,
             "--precision", precision, "-o", out]);
  return {
    c2: new Uint8Array(readFileSync(join(out, `inlay_c2.${format}`))),
    manifest: JSON.parse(readFileSync(join(out, "inlay_bake.json"), "utf8")),
  };
}
const equalBytes = (a, b) => a.length === b.length && a.every((value, i) => value === b[i]);

try {
  run(makeMaps, ["--size", String(size), "-o", dir]);
  const ktxLevels = {};
  for (const [precision, channelBytes, vkFormat] of [["f16", 2, 97], ["f32", 4, 109]]) {
    const { c2, manifest } = bake("ktx2", precision);
    check(manifest.width === size && manifest.levels === levels && manifest.solve === "exact",
          `${precision} manifest: ${manifest.width} texels, ${manifest.levels} levels, ${manifest.solve}`);
    const ktx = readKtx2(c2);
    check(ktx.vkFormat === vkFormat && ktx.typeSize === channelBytes,
          `${precision} KTX2 vkFormat ${ktx.vkFormat}, typeSize ${ktx.typeSize}`);
    check(ktx.pixelWidth === size && ktx.pixelHeight === size, `${precision} KTX2 dimensions`);
    check(ktx.levels.length === levels, `${precision} KTX2 level count ${ktx.levels.length}`);
    ktx.levels.forEach((level, k) => {
      const side = Math.max(1, size >> k);
      check(level.levelData.length === side * side * 4 * channelBytes,
            `${precision} KTX2 level ${k}: ${level.levelData.length} bytes`);
    });
    check(ktx.dataFormatDescriptor[0].samples.length === 4, `${precision} KTX2 DFD: RGBA`);
    ktxLevels[precision] = ktx.levels;
  }

  const dds = bake("dds", "f32").c2;
  const parsed = parseDds(dds.buffer.slice(dds.byteOffset, dds.byteOffset + dds.byteLength));
  check(parsed.format === "rgba32f", `DDS format ${parsed.format}`);
  check(parsed.shape[0] === size && parsed.shape[1] === size, `DDS shape ${parsed.shape}`);
  check(parsed.images.length === levels, `DDS mip count ${parsed.images.length}`);
  // parse-dds sizes levels as compressed blocks only (its lengths are NaN for rgba32f): it gives
  // the first level's offset and every level's shape; levels follow one another from there.
  check(parsed.images[0].offset === 148, `DDS first level at ${parsed.images[0].offset}`);
  let offset = 148;
  parsed.images.forEach((image, k) => {
    const side = Math.max(1, size >> k);
    check(image.shape[0] === side && image.shape[1] === side, `DDS level ${k} shape ${image.shape}`);
    const texels = dds.subarray(offset, offset + side * side * 16);
    check(equalBytes(texels, ktxLevels.f32[k].levelData), `DDS level ${k} equals KTX2 level ${k}`);
    offset += side * side * 16;
  });
  check(offset === dds.length, `DDS ends after the last level (${offset} of ${dds.length} bytes)`);
} finally {
  rmSync(dir, { recursive: true, force: true });
}
finish();
