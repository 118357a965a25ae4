#!/usr/bin/env bash
# Renders the engine comparison images into docs/images/ and writes their error and frame-time
# tables into docs/web-engines.md: three.js's (WebGLRenderer and WebGPURenderer) and Babylon.js's
# stock materials and the same materials with matc's Fresnel (the npm package's js/package/three,
# js/package/babylon) against the
# Monte-Carlo reference, in headless Chromium (a few minutes: the frame times are extra frames
# timed from outside).
#   examples/web/update-web-docs.sh [BUILD_DIR]   (default: build)
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-$root/build}
cmake --build "$build" --target matc matc_example_maps >/dev/null
for engine in three three-webgpu babylon; do
  "$root/tests/scripts/check_docs_block.sh" --update "$root/docs/web-engines.md" "$engine-reference" \
    node "$root/tests/js/check-$engine-reference.mjs" "$build/matc" "$root/examples/materials" \
    "$root/js/package" "$build/examples/textured/matc_example_maps" "$root/examples/textured" \
    --markdown --size 256 --images "$root/docs/images" --timing
done
