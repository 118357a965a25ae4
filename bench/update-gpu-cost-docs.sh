#!/usr/bin/env bash
# Regenerates the instruction-cost table of docs/performance.md (RADV's null device, no GPU).
#   bench/update-gpu-cost-docs.sh [BUILD_DIR]   (default: build)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
cmake --build "$build" --target matc_gpu_cost >/dev/null
"$root/tests/scripts/check_docs_block.sh" --update "$root/docs/performance.md" gpu-cost \
  "$build/bench/matc_gpu_cost"
