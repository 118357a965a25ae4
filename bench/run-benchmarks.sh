#!/usr/bin/env bash
# Runs the speed benchmarks and writes their medians into docs/performance.md.
#   bench/run-benchmarks.sh [BUILD_DIR]   (default: build; use a Release build)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
cmake --build "$build" --target matc_lut_benchmark >/dev/null

report=$(mktemp)
trap 'rm -f "$report" "$report.md"' EXIT
"$build/bench/matc_lut_benchmark" --benchmark_repetitions=5 --benchmark_report_aggregates_only=true \
  --benchmark_format=json >"$report"

build_type=$(sed -n 's/^CMAKE_BUILD_TYPE:[A-Z]*=//p' "$build/CMakeCache.txt")
node - "$report" "$build_type" >"$report.md" <<'JS'
const report = JSON.parse(require("fs").readFileSync(process.argv[2], "utf8"));
const c = report.context;
console.log(`Measured ${c.date.slice(0, 10)} on ${c.num_cpus} CPU(s) at ${c.mhz_per_cpu} MHz, ` +
            `matc built ${process.argv[3]}, median of 5 repetitions:\n`);
console.log("| table | samples per texel | threads | time (ms) | samples/s |");
console.log("|---|---:|---:|---:|---:|");
for (const b of report.benchmarks.filter((b) => b.aggregate_name === "median")) {
  const args = Object.fromEntries(b.run_name.split("/").slice(1).map((kv) => kv.split(":")));
  console.log(`| ${args.size}x${args.size} | ${args.samples} | ${args.threads} | ` +
              `${b.real_time.toFixed(1)} | ${(b["samples/s"] / 1e6).toFixed(0)} M |`);
}
JS
"$root/tests/scripts/check_docs_block.sh" --update "$root/docs/performance.md" lut-bake cat "$report.md"

# Our Fresnel against Schlick's in a 720p full-screen pass on Vulkan (lavapipe unless
# MATC_BENCH_DEVICE names another device).
cmake --build "$build" --target matc_fullscreen_cost >/dev/null
"$build/bench/matc_fullscreen_cost" ${MATC_BENCH_DEVICE:+--device "$MATC_BENCH_DEVICE"} >"$report.md"
"$root/tests/scripts/check_docs_block.sh" --update "$root/docs/performance.md" fullscreen-720p cat "$report.md"

# One build action per material (--no-shared) and the shared action, median wall times.
"$root/bench/per-material.sh" "$build" >"$report.md"
"$root/tests/scripts/check_docs_block.sh" --update "$root/docs/performance.md" per-material cat "$report.md"

# The Python module: F on a million cosines against the C++ runtime and plain numpy, and one
# batch call over 1,000 materials against the CLI.
"$root/bench/python-bench.sh" "$build" 1000 >"$report.md"
"$root/tests/scripts/check_docs_block.sh" --update "$root/docs/performance.md" python cat "$report.md"

# The npm package's WebAssembly library against the native library: compile and texts.
"$root/bench/wasm-compile.sh" "$build" >"$report.md"
"$root/tests/scripts/check_docs_block.sh" --update "$root/docs/performance.md" wasm-compile cat "$report.md"
"$root/bench/lookdev-latency.sh" "$build" >"$report.md"
"$root/tests/scripts/check_docs_block.sh" --update "$root/docs/performance.md" lookdev-latency cat "$report.md"

# Batch throughput and memory: 1,000 materials at -j 1 and -j 2 against a glslangValidator loop.
"$root/bench/batch-throughput.sh" "$build" 1000 >"$report.md"
"$root/tests/scripts/check_docs_block.sh" --update "$root/docs/performance.md" batch-throughput cat "$report.md"
