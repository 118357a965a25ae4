#!/usr/bin/env bash
# matc bake's speed (issue #15: an 8-bit 4096 x 4096 map pair, all mips, in <= 3 s on 2 cores):
# the example inlay at 4096 x 4096 (a realistic map pair: few distinct (r, g) pairs) and uniform
# noise (all 65,536 pairs of an 8-bit map pair: the per-pair solve's worst case), 8-bit sRGB PNG,
# KTX2 f16 C2 and C3 with full mip chains, -j 1 and -j 2; and the same inlay as float OpenEXR n
# and k maps (the coefficient-table path). Best of three runs each, with peak memory. Prints the
# Markdown table of docs/performance.md.
#   bench/bake-throughput.sh [BUILD_DIR] [SIZE]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
size=${2:-4096}
matc=$build/matc
maps=$build/examples/textured/matc_example_maps
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

"$maps" --size "$size" --pattern tiles --exr -o "$work"
"$maps" --size "$size" --pattern noise -o "$work"

# Best wall-clock seconds of three runs and the peak resident memory (MiB) of the last.
measure() {  # command...
  local best=""
  for _ in 1 2 3; do
    rm -rf "$work/out"
    /usr/bin/time -f "%e %M" -o "$work/time" "$@" -o "$work/out" >/dev/null 2>&1
    read -r seconds kilobytes <"$work/time"
    if [ -z "$best" ] || awk -v a="$seconds" -v b="$best" 'BEGIN { exit !(a < b) }'; then
      best=$seconds
    fi
  done
  echo "$best $((kilobytes / 1024))"
}
solved() { sed -n 's/.*"solved_pairs": \([0-9]*\).*/\1/p' "$work"/out/*_bake.json; }

echo "matc bake of a ${size} x ${size} map pair into KTX2 f16 C2 and C3 with full mip chains" \
  "($(nproc) hardware threads here); best of three runs, peak resident memory of the last."
echo
echo "| maps | solve | distinct (r, g) solved | -j 1 | -j 2 | peak memory |"
echo "|---|---|---:|---:|---:|---:|"
for pattern in inlaid_metals noise_metal; do
  args=(bake -q --reflectivity "$work/${pattern}_r.png" --edge-tint "$work/${pattern}_g.png")
  read -r j1 _ < <(measure "$matc" "${args[@]}" -j 1)
  read -r j2 memory < <(measure "$matc" "${args[@]}" -j 2)
  label=$([ "$pattern" = inlaid_metals ] && echo "example inlay, 8-bit sRGB PNG" ||
    echo "uniform noise, 8-bit sRGB PNG")
  echo "| $label | exact, per pair | $(solved) | ${j1} s | ${j2} s | ${memory} MiB |"
done
args=(bake -q --n "$work/inlaid_metals_n.exr" --k "$work/inlaid_metals_k.exr" --name inlay_ior)
read -r j1 _ < <(measure "$matc" "${args[@]}" -j 1)
read -r j2 memory < <(measure "$matc" "${args[@]}" -j 2)
echo "| example inlay as n, k, float OpenEXR | coefficient table | - | ${j1} s | ${j2} s | ${memory} MiB |"

# What the table path costs in accuracy: level 0's largest |F - exact| over texels, channels and
# cosines, the exact solve of the 8-bit maps beside the table on the float n, k maps of the same
# inlay (1024 x 1024: --error-map evaluates every texel's exact curve).
small=$work/small
"$maps" --size 1024 --pattern tiles --exr -o "$small"
max_error() { sed -n 's/.*"max_error_level0": \([0-9.e-]*\).*/\1/p' "$1"; }
"$matc" bake -q --reflectivity "$small/inlaid_metals_r.png" --edge-tint "$small/inlaid_metals_g.png" \
  --name exact -o "$work/accuracy"
"$matc" bake -q --n "$small/inlaid_metals_n.exr" --k "$small/inlaid_metals_k.exr" --name table \
  --error-map -o "$work/accuracy"
echo
printf 'Level 0 of the inlay against the exact curves (largest |F - exact| over texels, channels and\n'
printf 'cosines, 1024 x 1024): %.4f with the exact per-pair solve of the 8-bit maps, %.4f through\n' \
  "$(max_error "$work/accuracy/exact_bake.json")" "$(max_error "$work/accuracy/table_bake.json")"
printf 'the coefficient table from the float n, k maps (errors over the solve'"'"'s 401 cosines and the\n'
printf 'error map'"'"'s 65).\n'
