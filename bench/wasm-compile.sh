#!/usr/bin/env bash
# Compiling materials in WebAssembly (the npm package, in Node) against the native library, in one
# run: the public API's parse + compile and the four texts of every example material that names
# no file and of the measured metals bare and under a coat, one thread each, the fastest of 5
# passes; and the .wasm's size. Prints the Markdown block of docs/performance.md.
#   bench/wasm-compile.sh [BUILD_DIR]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --build "$build" --target matc_npm_package matc_api_compile_timing >/dev/null

node - "$root/examples/materials" "$build/npm" >"$work/materials.jsonl" <<'JS'
const fs = require("fs");
const [examples, npm] = process.argv.slice(2);
const lines = [];
for (const file of fs.readdirSync(examples).filter((f) => f.endsWith(".json")).sort()) {
  const text = fs.readFileSync(`${examples}/${file}`, "utf8");
  if (!/"file"\s*:/.test(text)) lines.push({ text, path: file });
}
import(require("path").resolve(npm, "index.mjs")).then(async ({ createMatc }) => {
  for (const preset of (await createMatc()).spectralPresets()) {
    lines.push({ text: JSON.stringify({ name: `m_${preset}`, spectral: { preset } }), path: `m_${preset}.json` });
    lines.push({ text: JSON.stringify({ name: `c_${preset}`, spectral: { preset }, coat: { ior: 1.5 } }),
                 path: `c_${preset}.json` });
  }
  for (const line of lines) console.log(JSON.stringify(line));
});
JS
count=$(wc -l <"$work/materials.jsonl")
read -r native_compile native_texts _ < <("$build/bench/matc_api_compile_timing" "$work/materials.jsonl" 5)
read -r wasm_compile wasm_texts _ < <(node "$root/bench/wasm_compile_timing.mjs" "$build/npm" "$work/materials.jsonl" 5)
wasm_size=$(stat -c %s "$build/npm/matc.wasm")
wasm_gzip=$(gzip -9 -c "$build/npm/matc.wasm" | wc -c)
node - "$count" "$native_compile" "$native_texts" "$wasm_compile" "$wasm_texts" "$wasm_size" "$wasm_gzip" "$(nproc)" "$(node --version)" <<'JS'
const [count, nc, nt, wc, wt, size, gzip, cpus, node] = process.argv.slice(2);
const per = (ms) => (Number(ms) / Number(count)).toFixed(3);
console.log(`Measured on ${cpus} CPU(s), one thread each, Node ${node}: ${count} materials (the example ` +
            `materials that name no file, every spectral preset bare and under a 1.5 coat), the fastest of 5 passes:\n`);
console.log("| per material | native library (ms) | WebAssembly in Node (ms) | ratio |");
console.log("|---|---:|---:|---:|");
console.log(`| parse + compile | ${per(nc)} | ${per(wc)} | ${(Number(wc) / Number(nc)).toFixed(2)}x |`);
console.log(`| the four texts (GLSL, HLSL, WGSL, JSON) | ${per(nt)} | ${per(wt)} | ${(Number(wt) / Number(nt)).toFixed(2)}x |`);
console.log(`\nmatc.wasm: ${(Number(size) / 1048576).toFixed(2)} MiB, ${(Number(gzip) / 1048576).toFixed(2)} MiB gzipped (gzip -9).`);
JS
