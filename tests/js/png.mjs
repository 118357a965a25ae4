// Writes 8-bit RGB PNG files with Node's zlib (no dependency): for the comparison images of
// docs/web-engines.md and the textures of the glTF assets the tests build.
import { writeFileSync } from "node:fs";
import { deflateSync } from "node:zlib";

const kCrcTable = Array.from({ length: 256 }, (_, n) => {
  let c = n;
  for (let k = 0; k < 8; ++k) c = c & 1 ? 0xedb88320 ^ (c >>> 1) : c >>> 1;
  return c >>> 0;
});

function crc32(bytes) {
  let c = 0xffffffff;
  for (const byte of bytes) c = kCrcTable[(c ^ byte) & 0xff] ^ (c >>> 8);
  return (c ^ 0xffffffff) >>> 0;
}

function chunk(type, data) {
  const body = Buffer.concat([Buffer.from(type, "ascii"), data]);
  const length = Buffer.alloc(4);
  length.writeUInt32BE(data.length);
  const crc = Buffer.alloc(4);
  crc.writeUInt32BE(crc32(body));
  return Buffer.concat([length, body, crc]);
}

// rgb: width * height * 3 bytes, first row at the top.
export function writePng(path, width, height, rgb) {
  writeFileSync(path, pngBytes(width, height, rgb));
}

// The PNG file's bytes (a texture for the glTF assets the tests build).
export function pngBytes(width, height, rgb) {
  const header = Buffer.alloc(13);
  header.writeUInt32BE(width, 0);
  header.writeUInt32BE(height, 4);
  header.set([8, 2, 0, 0, 0], 8);  // 8 bits, RGB, deflate, no filter method, no interlace
  const rows = Buffer.alloc((width * 3 + 1) * height);
  for (let y = 0; y < height; ++y) {
    rows[y * (width * 3 + 1)] = 0;  // filter: none
    rows.set(rgb.subarray(y * width * 3, (y + 1) * width * 3), y * (width * 3 + 1) + 1);
  }
  const signature = Buffer.from([0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a]);
  return Buffer.concat([signature, chunk("IHDR", header), chunk("IDAT", deflateSync(rows, { level: 9 })),
                        chunk("IEND", Buffer.alloc(0))]);
}

// Linear radiance to display: x / (1 + x) (Reinhard), then the sRGB transfer.
export function displayByte(linear) {
  const x = Math.max(0, linear) / (1 + Math.max(0, linear));
  const s = x <= 0.0031308 ? 12.92 * x : 1.055 * x ** (1 / 2.4) - 0.055;
  return Math.round(Math.min(1, s) * 255);
}
