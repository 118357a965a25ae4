#!/usr/bin/env bash
# Regenerates docs/images/lookdev.png and docs/images/lookdev_asset.png, the look-development page
# (js/package/lookdev/) in headless Chromium, from the staged npm package of BUILD_DIR (default: build).
#   scripts/update-lookdev-image.sh [BUILD_DIR]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
cmake --build "$build" --target matc_npm_package >/dev/null
node "$root/tests/js/lookdev-screenshot.mjs" "$build/npm" "$root/docs/images/lookdev.png"
node "$root/tests/js/lookdev-screenshot.mjs" "$build/npm" "$root/docs/images/lookdev_asset.png" asset
echo "wrote docs/images/lookdev.png and docs/images/lookdev_asset.png"
