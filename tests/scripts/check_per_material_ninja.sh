#!/usr/bin/env bash
# matc_add_materials(... PER_MATERIAL) with Ninja on 500 generated materials (one under a film, whose
# own table its step declares, and one under a film of index 1, the bare metal, with no table): the
# first build runs one shared step and one step per material, a
# second build does nothing, and touching one material reruns that material's step alone.
#   check_per_material_ninja.sh MATC SOURCE_DIR
set -euo pipefail
matc=$(realpath "$1")
source_dir=$(realpath "$2")
count=500
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/project/materials"
for i in $(seq -f %04g 1 "$count"); do
  # Reflectivity and edge tint spread over the artistic range; one file per material.
  r=$(( 10#$i % 90 + 5 )); g=$(( 10#$i * 7 % 100 ))
  printf '{"name": "m%s", "artistic": {"reflectivity": 0.%02d, "edge_tint": 0.%02d}}\n' \
    "$i" "$r" "$g" >"$work/project/materials/m$i.json"
done
# One of them under a film: its own table is one of its step's outputs (docs/thin-film.md).
printf '{"name": "m%s", "artistic": {"reflectivity": 0.6, "edge_tint": 0.5}, "film": {"ior": 2.0, "thickness": 120}}\n' \
  "$(printf %04g "$count")" >"$work/project/materials/m$(printf %04g "$count").json"
# A film of index 1 is air, the bare metal: no table (declared, it would be missing and rebuilt).
printf '{"name": "m%s", "artistic": {"reflectivity": 0.6, "edge_tint": 0.5}, "film": {"ior": 1, "thickness": 120}}\n' \
  "$(printf %04g $((count - 1)))" >"$work/project/materials/m$(printf %04g $((count - 1))).json"
cat >"$work/project/CMakeLists.txt" <<CMAKE
cmake_minimum_required(VERSION 3.25)
project(per_material LANGUAGES CXX)
add_executable(matc::cli IMPORTED)
set_target_properties(matc::cli PROPERTIES IMPORTED_LOCATION "$matc")
include("$source_dir/cmake/MatcAddMaterials.cmake")
file(GLOB materials CONFIGURE_DEPENDS "\${CMAKE_CURRENT_SOURCE_DIR}/materials/*.json")
file(WRITE "\${CMAKE_CURRENT_BINARY_DIR}/empty.cpp" "")
add_library(materials STATIC "\${CMAKE_CURRENT_BINARY_DIR}/empty.cpp")
matc_add_materials(TARGET materials OUTPUT_DIR generated MATERIALS \${materials}
                   EMIT glsl json lut LUT_FORMAT raw PER_MATERIAL)
CMAKE
cmake -S "$work/project" -B "$work/build" -G Ninja >/dev/null
cd "$work/build"
first=$(ninja -v)
steps=$(grep -c -- "--no-shared" <<<"$first" || true)
shared=$(grep -c -- "--shared-only" <<<"$first" || true)
echo "first build: $steps per-material steps, $shared shared step"
[[ $steps == "$count" && $shared == 1 ]] || { echo "FAIL: expected $count and 1"; exit 1; }
[[ $(ls generated/*.glsl | wc -l) == $((count + 1)) ]] || { echo "FAIL: missing outputs"; exit 1; }
film_table=generated/m$(printf %04g "$count").film.bin
[[ -f $film_table ]] && grep -q "$film_table" build.ninja ||
  { echo "FAIL: the filmed material's table is not a declared output ($film_table)"; exit 1; }
air_film_table=generated/m$(printf %04g $((count - 1))).film.bin
[[ ! -e $air_film_table ]] && ! grep -q "$air_film_table" build.ninja ||
  { echo "FAIL: a film of index 1 has a table ($air_film_table)"; exit 1; }
second=$(ninja -v)
grep -q "no work to do" <<<"$second" || { echo "FAIL: the second build was not a no-op"; exit 1; }
sleep 1
touch "$work/project/materials/m0042.json"
third=$(ninja -v)
reran=$(grep -c -- "--no-shared" <<<"$third" || true)
grep -q "m0042.json" <<<"$third" && [[ $reran == 1 ]] && ! grep -q -- "--shared-only" <<<"$third" ||
  { echo "FAIL: touching m0042.json reran $reran steps:"; echo "$third" | head; exit 1; }
echo "per-material Ninja edges: a no-op rebuild does nothing, one touched material reruns one step"
