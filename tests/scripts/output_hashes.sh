#!/usr/bin/env bash
# Prints a hash of every file matc writes for the example materials with every output kind, in
# every table format and basis (a basis per material too; and an embedded table, two bakes, an import): one line per file,
# "CONFIGURATION/FILE HASH" (SHA-256, 16 hex digits). tests/data/output_hashes.txt holds what the
# checked-in sources write; the output_hashes test compares, so a change that moves one byte of any output is seen. After
# an intended change:  tests/scripts/output_hashes.sh build/matc > tests/data/output_hashes.txt
#   output_hashes.sh MATC
set -euo pipefail
matc=$(realpath "${1:?usage: output_hashes.sh MATC}")
source_dir=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$source_dir"
materials=(examples/materials/*.json examples/materialx/metals.mtlx)
for format in ktx2 dds raw header; do
  for basis in powers extended paper f82; do
    "$matc" -q -o "$work/compile_${format}_$basis" --lut "$format" --basis "$basis" "${materials[@]}" 2>/dev/null
  done
done
# The default, a basis per material (--basis auto): the table a layer per basis, each material's
# outputs its own basis'.
for format in ktx2 raw header; do
  "$matc" -q -o "$work/compile_${format}_auto" --lut "$format" "${materials[@]}" 2>/dev/null
done
"$matc" -q -o "$work/compile_embedded" --embed-lut --embed-lut-size 8 --emit glsl,hlsl,spirv,header \
  "${materials[@]}" 2>/dev/null
"$matc" bake -q -o "$work/bake" --f0 --error-map --reflectivity 0.9,0.6,0.3 --edge-tint 0.5 \
  --name artistic 2>/dev/null
"$matc" bake -q -o "$work/bake" --format dds --precision f32 --n 0.2,0.4,1.2 --k 3,2.5,2 \
  --name ior 2>/dev/null
"$matc" import -q -o "$work/import" examples/materialx/metals.mtlx 2>/dev/null
cd "$work"
find . -type f | LC_ALL=C sort | xargs sha256sum | awk '{ sub("^\\./", "", $2); print $2, substr($1, 1, 16) }'
