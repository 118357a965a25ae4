// Reads the coefficient table matc writes (--emit coefficient-table) with independent readers:
// ktx-parse for KTX2, parse-dds for DDS. Each container's texel bytes must equal the raw output,
// and both must describe a two-channel (RG) float texture of the manifest's size.
//   node check-coefficient-table-files.mjs MATC_BINARY MATERIAL_FILE
import { spawnSync } from "node:child_process";
import { mkdtempSync, readFileSync, rmSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { read as readKtx2 } from "ktx-parse";
import parseDds from "parse-dds";
import { check, finish } from "./report.mjs";

const [matc, material] = process.argv.slice(2);
const dir = mkdtempSync(join(tmpdir(), "matc-coefficient-table-"));

function emit(format, precision) {
  const out = join(dir, `${format}_${precision}`);
  const run = spawnSync(matc, ["-q", "-o", out, "--emit", "coefficient-table", "--lut", format,
                               "--coefficient-table-precision", precision, material], { encoding: "utf8" });
  if (run.status !== 0) throw new Error(`matc failed: ${run.stderr}`);
  const extension = { raw: "bin", ktx2: "ktx2", dds: "dds" }[format];
  const path = join(out, `matc_coefficient_table.${extension}`);
  return {
    bytes: new Uint8Array(readFileSync(path)),
    manifest: JSON.parse(readFileSync(`${path}.json`, "utf8")),
  };
}
const equalBytes = (a, b) => a.length === b.length && a.every((value, i) => value === b[i]);

try {
  for (const [precision, channelBytes, vkFormat, dxgiFormat] of [["f16", 2, 83, 34],
                                                                  ["f32", 4, 103, 16]]) {
    const { bytes: raw, manifest } = emit("raw", precision);
    const [width, height] = manifest.size;
    check(width === height && width >= 2, `${precision} manifest size ${manifest.size}`);
    check(manifest.channels.length === 2 && manifest.precision === precision,
          `${precision} manifest channels and precision`);
    check(raw.length === width * height * 2 * channelBytes, `${precision} raw size ${raw.length}`);

    const ktx = readKtx2(emit("ktx2", precision).bytes);
    check(ktx.vkFormat === vkFormat, `${precision} KTX2 vkFormat ${ktx.vkFormat}`);
    check(ktx.typeSize === channelBytes, `${precision} KTX2 typeSize ${ktx.typeSize}`);
    check(ktx.pixelWidth === width && ktx.pixelHeight === height, `${precision} KTX2 dimensions`);
    check(ktx.levels.length === 1 && equalBytes(ktx.levels[0].levelData, raw),
          `${precision} KTX2 level data equals raw`);
    const dfd = ktx.dataFormatDescriptor[0];
    check(dfd.bytesPlane[0] === 2 * channelBytes, `${precision} KTX2 DFD bytesPlane0`);
    check(dfd.samples.length === 2, `${precision} KTX2 DFD sample count ${dfd.samples.length}`);
    dfd.samples.forEach((sample, i) => {
      check(sample.bitOffset === i * 8 * channelBytes && sample.bitLength === 8 * channelBytes - 1,
            `${precision} KTX2 DFD sample ${i} bits`);
      check(sample.channelType === (i | 0xc0), `${precision} KTX2 DFD sample ${i} channel type`);
    });

    const dds = emit("dds", precision).bytes;
    check(equalBytes(dds.subarray(148), raw), `${precision} DDS texels (after 148-byte header)`);
    // parse-dds decodes only rgba32f; reaching the DXGI format check proves it read the header.
    let message = "";
    try {
      parseDds(dds.buffer.slice(dds.byteOffset, dds.byteOffset + dds.byteLength));
    } catch (error) {
      message = error.message;
    }
    check(message === `Unsupported DX10 texture format ${dxgiFormat}`,
          `${precision} DDS: '${message}'`);
  }
} finally {
  rmSync(dir, { recursive: true, force: true });
}
finish();
