#!/usr/bin/env bash
# The size of what each shader target writes, as a Markdown table for docs/shaders.md: the shared
# library (default build, which includes the textured-metal and area-light functions) and one
# material's snippet, raw and gzip -9 (what a web page ships).
#   bench/shader-sizes.sh MATC MATERIAL.json
set -euo pipefail
matc=$1
material=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$matc" -q -o "$work" --emit glsl,hlsl,wgsl "$material"
name=$(basename "$material" .json)
bytes() { wc -c <"$1" | tr -d ' '; }
gzipped() { gzip -9 -n -c "$1" | wc -c | tr -d ' '; }
echo "| target | matc_fresnel (bytes) | gzip -9 | $name (bytes) | gzip -9 |"
echo "|---|---:|---:|---:|---:|"
for language in glsl hlsl wgsl; do
  library="$work/matc_fresnel.$language"
  snippet="$work/$name.$language"
  echo "| $language | $(bytes "$library") | $(gzipped "$library") | $(bytes "$snippet") | $(gzipped "$snippet") |"
done
