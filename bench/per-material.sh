#!/usr/bin/env bash
# What one build action costs: the median wall time of repeated matc runs for one material's own
# files (--no-shared), per output set and kind of input, beside the shared action and the old
# one-material batch. Prints the Markdown table of docs/performance.md ("Per-material actions").
#   bench/per-material.sh [BUILD_DIR] [RUNS]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
runs=${2:-21}
matc=$build/matc
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
artistic=$root/examples/materials/tinted_steel.json
spectral=$root/examples/materials/copper.json
filmed=$root/examples/materials/titanium_anodised_blue.json
coated=$root/examples/materials/copper_lacquered.json
film_coated=$root/examples/materials/titanium_anodised_lacquered.json
film_stack=$root/tests/data/film_stack/titanium_heat_tint.json
bare_titanium=$root/examples/materials/titanium.json

# Median wall time in milliseconds of `runs` runs of a command.
median_ms() {
  local times=()
  for _ in $(seq "$runs"); do
    local start end
    start=$(date +%s%N)
    "$@" >/dev/null 2>&1
    end=$(date +%s%N)
    times+=($(( (end - start) / 1000 )))
  done
  printf '%s\n' "${times[@]}" | sort -n | awk '{ a[NR] = $1 } END { printf "%.1f", a[int((NR + 1) / 2)] / 1000 }'
}

"$matc" -q -o "$work/warm" "$artistic"  # page in the binary once
row() {  # label command...
  local label=$1
  shift
  echo "| $label | $(median_ms "$@") |"
}
echo "Measured on $(nproc) CPU(s), median of $runs runs each:"
echo
echo "| action | wall (ms) |"
echo "|---|---:|"
row "\`--no-shared --emit glsl,hlsl,wgsl,json\`, artistic material" \
  "$matc" -q -o "$work/a" --no-shared --emit glsl,hlsl,wgsl,json "$artistic"
row "\`--no-shared --emit glsl,hlsl,wgsl,json\`, spectral preset (copper)" \
  "$matc" -q -o "$work/b" --no-shared --emit glsl,hlsl,wgsl,json "$spectral"
row "\`--no-shared\` (every own file: + SPIR-V, C header), artistic" \
  "$matc" -q -o "$work/c" --no-shared "$artistic"
row "\`--no-shared\`, spectral preset" "$matc" -q -o "$work/d" --no-shared "$spectral"
row "\`--no-shared\`, spectral preset (titanium)" "$matc" -q -o "$work/g" --no-shared "$bare_titanium"
row "\`--no-shared\`, the same titanium under a 45 nm film" \
  "$matc" -q -o "$work/h" --no-shared "$filmed"
row "\`--no-shared\`, a coated spectral preset (copper under a lacquer)" \
  "$matc" -q -o "$work/i" --no-shared "$coated"
row "\`--no-shared\`, the filmed titanium under a clear lacquer" \
  "$matc" -q -o "$work/j" --no-shared "$film_coated"
row "\`--no-shared\`, titanium under a film of a thickness per pixel (20-250 nm)" \
  "$matc" -q -o "$work/k" --no-shared "$film_stack"
row "\`--no-shared --emit glsl,hlsl,wgsl,json,lut\`, the same (no C header)" \
  "$matc" -q -o "$work/l" --no-shared --emit glsl,hlsl,wgsl,json,lut "$film_stack"
row "\`--shared-only\` (libraries, SPIR-V library, 128x128 table bake, tables)" \
  "$matc" -q -o "$work/e" --shared-only
row "one-material batch, every output (own and shared files, manifest)" \
  "$matc" -q -o "$work/f" "$artistic"
