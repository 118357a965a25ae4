// Reads the LTC table matc writes (--emit ltc) with independent readers: ktx-parse for KTX2,
// parse-dds for DDS. Both containers' texel bytes must equal the raw output, describe an RGBA
// 32-bit float texture of the manifest's size, and hold M^-1 with a = 1, b = c = 0 at normal
// incidence (the last column).
//   node check-ltc-files.mjs MATC_BINARY MATERIAL_FILE
import { spawnSync } from "node:child_process";
import { mkdtempSync, readFileSync, rmSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { read as readKtx2 } from "ktx-parse";
import parseDds from "parse-dds";
import { check, finish } from "./report.mjs";

const [matc, material] = process.argv.slice(2);
const dir = mkdtempSync(join(tmpdir(), "matc-ltc-"));

function emit(format) {
  const out = join(dir, format);
  const run = spawnSync(matc, ["-q", "-o", out, "--emit", "ltc", "--lut", format, material],
                        { encoding: "utf8" });
  if (run.status !== 0) throw new Error(`matc failed: ${run.stderr}`);
  const extension = { raw: "bin", ktx2: "ktx2", dds: "dds" }[format];
  const path = join(out, `matc_ltc.${extension}`);
  return {
    bytes: new Uint8Array(readFileSync(path)),
    manifest: JSON.parse(readFileSync(`${path}.json`, "utf8")),
  };
}
const equalBytes = (a, b) => a.length === b.length && a.every((value, i) => value === b[i]);

try {
  const { bytes: raw, manifest } = emit("raw");
  const [width, height] = manifest.size;
  check(width === height && width >= 2, `manifest size ${manifest.size}`);
  check(manifest.precision === "f32" && manifest.channels.join() === "a,b,c,d",
        "manifest precision and channels");
  check(raw.length === width * height * 16, `raw size ${raw.length}`);
  const texels = new Float32Array(raw.buffer, raw.byteOffset, raw.length / 4);
  for (let y = 1; y < height; ++y) {
    const i = (y * width + width - 1) * 4;
    check(Math.abs(texels[i] - 1) < 1e-5 && Math.abs(texels[i + 1]) < 1e-6 &&
          Math.abs(texels[i + 2]) < 1e-6 && texels[i + 3] > 0, `normal incidence, row ${y}`);
  }

  const ktx = readKtx2(emit("ktx2").bytes);
  check(ktx.vkFormat === 109, `KTX2 vkFormat ${ktx.vkFormat} (R32G32B32A32_SFLOAT)`);
  check(ktx.typeSize === 4, `KTX2 typeSize ${ktx.typeSize}`);
  check(ktx.pixelWidth === width && ktx.pixelHeight === height, "KTX2 dimensions");
  check(ktx.levels.length === 1 && equalBytes(ktx.levels[0].levelData, raw),
        "KTX2 level data equals raw");
  const dfd = ktx.dataFormatDescriptor[0];
  check(dfd.bytesPlane[0] === 16 && dfd.samples.length === 4, "KTX2 DFD plane and samples");

  const dds = emit("dds").bytes;
  const parsed = parseDds(dds.buffer.slice(dds.byteOffset, dds.byteOffset + dds.byteLength));
  check(parsed.format === "rgba32f", `DDS format ${parsed.format}`);
  check(parsed.shape[0] === width && parsed.shape[1] === height, "DDS shape");
  check(parsed.images.length === 1 && equalBytes(dds.subarray(parsed.images[0].offset), raw),
        "DDS texels equal raw");
} finally {
  rmSync(dir, { recursive: true, force: true });
}
finish();
