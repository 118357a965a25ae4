#!/usr/bin/env bash
# Runs every example material's shaders on the Vulkan device (lavapipe unless MATC_BENCH_DEVICE
# names another) and writes the report into docs/validation.md.
#   bench/update-validation-docs.sh [BUILD_DIR]   (default: build)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
cmake --build "$build" --target matc >/dev/null
report=$(mktemp)
trap 'rm -f "$report"' EXIT
{
  echo '```'
  (cd "$root" && "$build/matc" validate --vk-validation ${MATC_BENCH_DEVICE:+--device "$MATC_BENCH_DEVICE"} \
    examples/materials/*.json)
  echo '```'
} >"$report"
"$root/tests/scripts/check_docs_block.sh" --update "$root/docs/validation.md" validate-examples cat "$report"
