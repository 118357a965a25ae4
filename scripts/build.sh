#!/usr/bin/env bash
# Installs what matc needs, builds it (which also bakes the example textured metal into
# build/examples/textured/baked/), and compiles the example materials and MaterialX documents into
# build/examples/.
# Extra CMake arguments can be passed in MATC_CMAKE_ARGS.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"

bash scripts/install-deps.sh
# shellcheck disable=SC2086  # MATC_CMAKE_ARGS is a list of words
cmake -S . -B build -G Ninja ${MATC_CMAKE_ARGS:-}
cmake --build build
# --validate: every material's GLSL and HLSL shaders run on lavapipe against the CPU runtime first.
# examples/materialx/*.mtlx: MaterialX documents compiled as they are (docs/interchange.md).
./build/matc --validate -o build/examples examples/materials/*.json examples/materialx/*.mtlx
