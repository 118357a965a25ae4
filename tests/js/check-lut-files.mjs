// Reads the LUT files matc writes with independent readers: ktx-parse for KTX2, parse-dds for
// DDS. Each container's texel bytes must equal the raw output of the same table.
//   node check-lut-files.mjs MATC_BINARY
import { spawnSync } from "node:child_process";
import { mkdtempSync, readFileSync, rmSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { read as readKtx2 } from "ktx-parse";
import parseDds from "parse-dds";
import { check, finish } from "./report.mjs";

const matc = process.argv[2];
const dir = mkdtempSync(join(tmpdir(), "matc-lut-"));
const size = 16;

function bake(name, format, precision) {
  const path = join(dir, name);
  const run = spawnSync(matc, ["lut", "-o", path, "--format", format, "--precision", precision,
                               "--size", String(size), "--samples", "64"], { encoding: "utf8" });
  if (run.status !== 0) throw new Error(`matc lut failed: ${run.stderr}`);
  return new Uint8Array(readFileSync(path));
}
const equalBytes = (a, b) => a.length === b.length && a.every((value, i) => value === b[i]);

try {
  for (const [precision, channelBytes, vkFormat] of [["f16", 2, 97], ["f32", 4, 109]]) {
    const raw = bake(`lut_${precision}.bin`, "raw", precision);
    check(raw.length === size * size * 4 * channelBytes, `${precision} raw size ${raw.length}`);

    const ktx = readKtx2(bake(`lut_${precision}.ktx2`, "ktx2", precision));
    check(ktx.vkFormat === vkFormat, `${precision} KTX2 vkFormat ${ktx.vkFormat}`);
    check(ktx.typeSize === channelBytes, `${precision} KTX2 typeSize ${ktx.typeSize}`);
    check(ktx.pixelWidth === size && ktx.pixelHeight === size && ktx.pixelDepth === 0,
          `${precision} KTX2 dimensions`);
    check(ktx.faceCount === 1 && ktx.layerCount === 0 && ktx.levels.length === 1,
          `${precision} KTX2 faces/layers/levels`);
    check(ktx.supercompressionScheme === 0, `${precision} KTX2 supercompression`);
    check(equalBytes(ktx.levels[0].levelData, raw), `${precision} KTX2 level data equals raw`);
    check(ktx.levels[0].uncompressedByteLength === raw.length,
          `${precision} KTX2 uncompressedByteLength`);
    const dfd = ktx.dataFormatDescriptor[0];
    check(dfd.colorModel === 1 && dfd.colorPrimaries === 1 && dfd.transferFunction === 1,
          `${precision} KTX2 DFD model/primaries/transfer`);
    check(dfd.bytesPlane[0] === 4 * channelBytes, `${precision} KTX2 DFD bytesPlane0`);
    check(dfd.samples.length === 4, `${precision} KTX2 DFD sample count`);
    dfd.samples.forEach((sample, i) => {
      check(sample.bitOffset === i * 8 * channelBytes && sample.bitLength === 8 * channelBytes - 1,
            `${precision} KTX2 DFD sample ${i} bits`);
      check(sample.channelType === ([0, 1, 2, 15][i] | 0xc0),
            `${precision} KTX2 DFD sample ${i} channel type ${sample.channelType}`);
    });
    check(String(ktx.keyValue.KTXwriter).startsWith("matc "), `${precision} KTX2 KTXwriter`);

    const dds = bake(`lut_${precision}.dds`, "dds", precision);
    check(equalBytes(dds.subarray(148), raw), `${precision} DDS texels (after 148-byte header)`);
    if (precision === "f32") {
      const parsed = parseDds(dds.buffer.slice(dds.byteOffset, dds.byteOffset + dds.byteLength));
      check(parsed.format === "rgba32f", `DDS format ${parsed.format}`);
      check(parsed.shape[0] === size && parsed.shape[1] === size, "DDS shape");
      check(parsed.images.length === 1 && parsed.images[0].offset === 148, "DDS image offset");
    } else {
      // parse-dds decodes only rgba32f; reaching the DXGI format check proves it read the header.
      let message = "";
      try {
        parseDds(dds.buffer.slice(dds.byteOffset, dds.byteOffset + dds.byteLength));
      } catch (error) {
        message = error.message;
      }
      check(message === "Unsupported DX10 texture format 10", `f16 DDS: '${message}'`);
    }
  }
} finally {
  rmSync(dir, { recursive: true, force: true });
}
finish();
