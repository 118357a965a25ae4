#!/usr/bin/env bash
# A very large batch: N generated artistic materials (default 100,000) compiled with every output
# at -j 2 in one matc run, and the same at N/10: wall time, materials per second and peak resident
# memory (which must barely grow with N). About 3 GB of outputs at N = 100,000. Prints the Markdown
# table of docs/performance.md ("A very large batch"); to update it:
#   tests/scripts/check_docs_block.sh --update docs/performance.md large-batch bench/large-batch.sh
#   bench/large-batch.sh [BUILD_DIR] [N]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
count=${2:-100000}
matc=$(realpath "$build/matc")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# shellcheck source=bench/generated-materials.sh
source "$root/bench/generated-materials.sh"

echo "Measured on $(nproc) CPU(s), generated artistic materials, every output, one \`matc -j 2\` run each:"
echo
echo "| materials | time (s) | materials/s | peak memory (MiB) |"
echo "|---:|---:|---:|---:|"
for n in $((count / 10)) "$count"; do
  generate_materials "$work/materials_$n" "$n" 2026
  # One run; 100,000 paths do not fit on a command line: --files-from reads them from a list.
  find "$work/materials_$n" -name '*.json' | sort >"$work/list_$n"
  /usr/bin/time -f "%e %M" -o "$work/time" \
    "$matc" -q -j 2 -o "$work/out_$n" --files-from "$work/list_$n" >/dev/null 2>&1
  read -r seconds kilobytes <"$work/time"
  echo "| $n | $seconds | $(awk -v n="$n" -v s="$seconds" 'BEGIN { printf "%.0f", n / s }') | $((kilobytes / 1024)) |"
  rm -rf "$work/out_$n" "$work/materials_$n"
done
