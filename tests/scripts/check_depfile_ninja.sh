#!/usr/bin/env bash
# Ninja reads matc's depfile: a second build does nothing; touching the spectral file a material
# names (not on the command line) rebuilds; so does touching the material file. matc leaves
# outputs whose bytes did not change untouched, so the rule needs `restat = 1` (CMake's custom
# commands have it).
#   check_depfile_ninja.sh MATC EXAMPLES_DIR
set -euo pipefail
matc=$1
examples=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/materials/spectra"
cp "$examples/gold_measured_file.json" "$work/materials/"
cp "$examples/spectra/gold_pbrt_v4.csv" "$work/materials/spectra/"
cat >"$work/build.ninja" <<NINJA
rule matc
  command = $matc -q --depfile out/gold.d -o out \$in
  depfile = out/gold.d
  deps = gcc
  restat = 1
build out/gold_measured_file.glsl: matc materials/gold_measured_file.json
NINJA
cd "$work"
# Ninja's whole output first: `ninja | grep -q` fails under pipefail when grep stops reading early
# (gold's out-of-gamut note follows the line it matches).
ran() { local out; out=$(ninja); grep -q "$1" <<<"$out"; }
ran "matc" || { echo "first build did not run matc"; exit 1; }
ran "no work to do" || { echo "second build was not a no-op"; exit 1; }
sleep 1
touch materials/spectra/gold_pbrt_v4.csv
ran "matc" || { echo "touching the spectral file did not rebuild"; exit 1; }
ran "no work to do" || { echo "rebuild was not stable"; exit 1; }
sleep 1
touch materials/gold_measured_file.json
ran "matc" || { echo "touching the material did not rebuild"; exit 1; }
echo "depfile: Ninja rebuilds on every input and only then"
