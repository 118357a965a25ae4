#!/usr/bin/env bash
# Builds libmatc in WebAssembly (js/, Debian's emscripten) into BUILD_DIR/wasm, stages the npm
# package in BUILD_DIR/npm (the tables written by the native matc) and packs it into
# BUILD_DIR/matc-<version>.tgz (docs/web.md).
#   scripts/build-wasm.sh BUILD_DIR MATC
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
build=$(realpath -m "${1:?usage: build-wasm.sh BUILD_DIR MATC}")
matc=$(realpath "${2:?usage: build-wasm.sh BUILD_DIR MATC}")
# emscripten's optimiser runs Node with Debian's acorn (shared/notes/toolchain.md).
export NODE_PATH=/usr/share/nodejs${NODE_PATH:+:$NODE_PATH}
if [ ! -f "$build/wasm/build.ninja" ]; then
  emcmake cmake -S "$repo/js" -B "$build/wasm" -G Ninja -DMATC_WERROR=ON >/dev/null
fi
cmake --build "$build/wasm"
# The main build runs this every time: stage and pack only when an input is newer than the tarball
# (or the staged folder is gone).
tarball=$(find "$build" -maxdepth 1 -name 'matc-*.tgz' -print -quit)
if [ -n "$tarball" ] && [ -f "$build/npm/package.json" ]; then
  newer=$(find "$build/wasm/matc.mjs" "$build/wasm/matc.wasm" "$repo/js/package" "$matc" \
            "$repo/CMakeLists.txt" -newer "$tarball" -print -quit)
  [ -n "$newer" ] || exit 0
fi
node "$repo/js/package/stage.mjs" "$build/wasm" "$build/npm" "$matc"
rm -f "$build"/matc-*.tgz
(cd "$build" && npm pack --silent ./npm >/dev/null)
