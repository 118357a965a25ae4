#!/usr/bin/env bash
# The look-development page's response to its controls and its frame time in headless Chromium
# (SwiftShader): bench/lookdev_latency.mjs on the staged npm package. Prints the Markdown block of
# docs/performance.md.
#   bench/lookdev-latency.sh [BUILD_DIR]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
cmake --build "$build" --target matc_npm_package >/dev/null
node "$root/bench/lookdev_latency.mjs" "$build/npm" 20
