#!/usr/bin/env bash
# Regenerates the area-light studies of docs/ltc.md: the LTC fit's quality (the shipped table and
# tables fitted in-process to the L1 and Heitz et al.'s objectives, on the previous view axis and
# with two variants of the polygon objective) per texel and at random views, the floor of the
# LTC's form on the held-out quads (each texel fitted to those quads themselves), and LTC with
# ours, Schlick's and the exact preintegrated Fresnel against the exact integral over a grid, for
# every example material (about 16 minutes on 2 cores: it fits five tables and the floor); then
# the quality level against the one shape on random quads (1.5 more minutes).
#   bench/area-light-study.sh [BUILD_DIR]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
cmake --build "$build" --target matc_area_light_study matc_area_light_quality_study >/dev/null
table=$(mktemp)
trap 'rm -f "$table"' EXIT
"$build/bench/matc_area_light_study" --samples 16384 --compare-objectives \
  "$root"/examples/materials/*.json >"$table"
"$root/tests/scripts/check_docs_block.sh" --update "$root/docs/ltc.md" area-light-study cat "$table"
"$build/bench/matc_area_light_quality_study" --compare-weights "$root"/examples/materials/*.json \
  >"$table"
"$root/tests/scripts/check_docs_block.sh" --update "$root/docs/ltc.md" area-light-quality cat "$table"
