#!/usr/bin/env bash
# Renders the comparison images into docs/images/ and writes their error table into
# docs/rendering.md (the talk's Figure 2 material and beryllium).
#   examples/render/update-images.sh [BUILD_DIR]   (default: build)
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-$root/build}
cmake --build "$build" --target matc_render >/dev/null
table=$(mktemp)
trap 'rm -f "$table"' EXIT
"$build/examples/render/matc_render" --size 256 --samples 4096 -o "$root/docs/images" \
  "$root/examples/materials/figure2_edge_tint.json" "$root/examples/materials/beryllium.json" \
  >"$table"
"$root/tests/scripts/check_docs_block.sh" --update "$root/docs/rendering.md" comparison-renders cat "$table"
# The same renders with the authors' basis (tables only; the images stay the default basis').
paper=$(mktemp -d)
trap 'rm -f "$table"; rm -rf "$paper"' EXIT
"$build/examples/render/matc_render" --size 256 --samples 4096 --basis paper -o "$paper" \
  "$root/examples/materials/figure2_edge_tint.json" "$root/examples/materials/beryllium.json" \
  >"$table"
"$root/tests/scripts/check_docs_block.sh" --update "$root/docs/rendering.md" comparison-renders-paper \
  cat "$table"
# A metal under a thin film: the anodised titanium example through its own table.
"$build/examples/render/matc_render" --size 256 --samples 4096 -o "$root/docs/images" \
  "$root/examples/materials/titanium_anodised_blue.json" >"$table"
"$root/tests/scripts/check_docs_block.sh" --update "$root/docs/rendering.md" film-render cat "$table"
# Coated metals: copper under a warm lacquer and the glTF car paint, both lobes, beside the
# engines' F0-in-coat Schlick and three.js's clear coat.
cmake --build "$build" --target matc_coated_render >/dev/null
"$build/examples/render/matc_coated_render" --size 256 --samples 4096 -o "$root/docs/images" \
  "$root/examples/materials/copper_lacquered.json" "$root/examples/gltf/car_paint.gltf" >"$table"
"$root/tests/scripts/check_docs_block.sh" --update "$root/docs/rendering.md" coated-render cat "$table"
# The textured render: per-pixel reflectivity and edge tint, the coefficient-table path.
cmake --build "$build" --target matc_textured_render >/dev/null
"$build/examples/render/matc_textured_render" --size 256 --samples 4096 -o "$root/docs/images" \
  >"$table"
"$root/tests/scripts/check_docs_block.sh" --update "$root/docs/rendering.md" textured-render cat "$table"
# The baked-texture render: coefficient textures of `matc bake` vs the maps' own mips, on the
# example maps.
cmake --build "$build" --target matc_baked_render matc_example_maps >/dev/null
maps=$(mktemp -d)
trap 'rm -f "$table"; rm -rf "$paper" "$maps"' EXIT
"$build/examples/textured/matc_example_maps" --size 512 -o "$maps"
"$build/examples/render/matc_baked_render" --size 256 -o "$root/docs/images" \
  --reflectivity "$maps/inlaid_metals_r.png" --edge-tint "$maps/inlaid_metals_g.png" >"$table"
"$root/tests/scripts/check_docs_block.sh" --update "$root/docs/rendering.md" baked-render cat "$table"
# Area lights (LTC): every bare example material for the table (coated ones are the coated
# render's; the filmed titanium through its own table), the Figure 2 material's and beryllium's
# images into docs/images.
cmake --build "$build" --target matc_area_light_render >/dev/null
area=$(mktemp -d)
trap 'rm -f "$table"; rm -rf "$paper" "$maps" "$area"' EXIT
mapfile -t bare < <(grep -L '"coat"' "$root"/examples/materials/*.json)
"$build/examples/render/matc_area_light_render" --size 256 --samples 4096 -o "$area" \
  "${bare[@]}" >"$table"
for name in figure2_edge_tint beryllium; do
  cp "$area/${name}_area.png" "$area/${name}_area_difference.png" \
    "$area/${name}_area_fresnel_difference.png" "$root/docs/images/"
done
"$root/tests/scripts/check_docs_block.sh" --update "$root/docs/rendering.md" area-light-render cat "$table"
