#!/usr/bin/env bash
# Regenerates the measured tables in docs/shaders.md (SPIR-V cost against Schlick, embedded table,
# closed form).
#   bench/update-shader-docs.sh [BUILD_DIR]   (default: build)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
cmake --build "$build" --target matc_shader_cost matc >/dev/null
tool="$build/bench/matc_shader_cost"
"$root/tests/scripts/check_docs_block.sh" --update "$root/docs/shaders.md" shader-cost "$tool"
"$root/tests/scripts/check_docs_block.sh" --update "$root/docs/shaders.md" embedded-lut "$tool" --embedded
"$root/tests/scripts/check_docs_block.sh" --update "$root/docs/shaders.md" closed-form "$tool" --closed-form
"$root/tests/scripts/check_docs_block.sh" --update "$root/docs/shaders.md" basis-polynomial \
  "$root/bench/fenced.sh" "$build/matc" basis
"$root/tests/scripts/check_docs_block.sh" --update "$root/docs/shaders.md" basis-polynomial-extended \
  "$root/bench/fenced.sh" "$build/matc" basis --basis extended
"$root/tests/scripts/check_docs_block.sh" --update "$root/docs/shaders.md" basis-polynomial-paper \
  "$root/bench/fenced.sh" "$build/matc" basis --basis paper
"$root/tests/scripts/check_docs_block.sh" --update "$root/docs/shaders.md" basis-polynomial-f82 \
  "$root/bench/fenced.sh" "$build/matc" basis --basis f82
"$root/tests/scripts/check_docs_block.sh" --update "$root/docs/shaders.md" shader-sizes \
  "$root/bench/shader-sizes.sh" "$build/matc" "$root/examples/materials/copper.json"
"$root/tests/scripts/check_docs_block.sh" --update "$root/docs/shaders.md" three-example \
  "$root/bench/fenced.sh" cat "$root/examples/web/matc-three.mjs"
"$root/tests/scripts/check_docs_block.sh" --update "$root/docs/shaders.md" webgpu-example \
  "$root/bench/fenced.sh" cat "$root/examples/web/specular.wgsl"
