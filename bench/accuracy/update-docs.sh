#!/usr/bin/env bash
# Regenerates the measured tables in docs/accuracy.md and the summary in README.md.
#   bench/accuracy/update-docs.sh [BUILD_DIR]   (default: build)
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-$root/build}
cmake --build "$build" --target matc_accuracy_table >/dev/null
tool="$build/bench/matc_accuracy_table"
"$root/tests/scripts/check_docs_block.sh" --update "$root/docs/accuracy.md" accuracy-tables "$tool"
"$root/tests/scripts/check_docs_block.sh" --update "$root/docs/accuracy.md" lut-accuracy "$tool" --lut
"$root/tests/scripts/check_docs_block.sh" --update "$root/README.md" accuracy-summary "$tool" --summary
"$root/tests/scripts/check_docs_block.sh" --update "$root/docs/accuracy.md" f82-tint "$tool" --f82-tint
"$root/tests/scripts/check_docs_block.sh" --update "$root/docs/accuracy.md" color-spaces "$tool" \
  --color-spaces
# Coated metals against the exact layered reflectance, and the coated examples (docs/coating.md).
cmake --build "$build" --target matc_coated_accuracy >/dev/null
"$root/tests/scripts/check_docs_block.sh" --update "$root/docs/coating.md" coated-accuracy \
  "$build/bench/matc_coated_accuracy"
"$root/tests/scripts/check_docs_block.sh" --update "$root/docs/coating.md" coated-examples \
  "$build/bench/matc_coated_accuracy" --examples "$root/examples/materials/copper_lacquered.json" \
  "$root/examples/materialx/standard_surface_copper.mtlx" \
  "$root/examples/materialx/open_pbr_lacquered_gold.mtlx"
# Which shipped basis each kind of material wants (about 3 s): the per-material rule of issue #66.
cmake --build "$build" --target matc_basis_choice_study >/dev/null
"$root/tests/scripts/check_docs_block.sh" --update "$root/docs/accuracy.md" basis-choice \
  "$build/bench/matc_basis_choice_study"
# A thin film over a metal (about 15 s of CPU; no test reruns it: optics' unit tests hold the
# physics, tests/unit/optics/thin_film_test.cpp).
cmake --build "$build" --target matc_thin_film_study >/dev/null
"$root/tests/scripts/check_docs_block.sh" --update "$root/docs/accuracy.md" thin-film-study \
  "$build/bench/matc_thin_film_study"
# How finely a table must sample a filmed metal's curve (about a minute on 2 cores; no test reruns
# it), and what a film over an RGB metal costs (3 s; thin_film_rgb_docs_current).
cmake --build "$build" --target matc_thin_film_table_study matc_thin_film_rgb_study >/dev/null
"$root/tests/scripts/check_docs_block.sh" --update "$root/docs/accuracy.md" thin-film-table-study \
  "$build/bench/matc_thin_film_table_study"
"$root/tests/scripts/check_docs_block.sh" --update "$root/docs/accuracy.md" thin-film-rgb-study \
  "$build/bench/matc_thin_film_rgb_study"
# A film under a coat: the table against the shortcuts (about 25 s on 2 cores; no test reruns it).
cmake --build "$build" --target matc_thin_film_coat_study >/dev/null
"$root/tests/scripts/check_docs_block.sh" --update "$root/docs/accuracy.md" thin-film-coat-study \
  "$build/bench/matc_thin_film_coat_study"
# What a shader could evaluate for a thickness per pixel (about 3 minutes on 2 cores; no test
# reruns it).
cmake --build "$build" --target matc_thin_film_thickness_study >/dev/null
"$root/tests/scripts/check_docs_block.sh" --update "$root/docs/accuracy.md" \
  thin-film-thickness-study "$build/bench/matc_thin_film_thickness_study"
# What a filmed metal's image light needs (about a minute of CPU; no test reruns it).
cmake --build "$build" --target matc_thin_film_image_light_study >/dev/null
"$root/tests/scripts/check_docs_block.sh" --update "$root/docs/accuracy.md" \
  thin-film-image-light-study "$build/bench/matc_thin_film_image_light_study"
# The basis study (about 1.5 minutes on 2 cores; no test reruns it, the unit tests hold the
# shipped basis to the targets it was chosen for).
cmake --build "$build" --target matc_basis_study >/dev/null
"$root/tests/scripts/check_docs_block.sh" --update "$root/docs/accuracy.md" basis-study \
  "$build/bench/matc_basis_study"
# The closed-form basis study (about 10 s on 2 cores): which powers of 1 - mu the default uses.
cmake --build "$build" --target matc_closed_form_basis_study >/dev/null
"$root/tests/scripts/check_docs_block.sh" --update "$root/docs/accuracy.md" closed-form-basis-study \
  "$build/bench/matc_closed_form_basis_study"
# Whether a basis could fit F82-tint materials too (about 40 s on 2 cores).
cmake --build "$build" --target matc_f82_basis_study >/dev/null
"$root/tests/scripts/check_docs_block.sh" --update "$root/docs/accuracy.md" f82-basis-study \
  "$build/bench/matc_f82_basis_study"
# The coefficient-table study (about 20 s on 2 cores; the unit tests hold the shipped table to the
# targets it was chosen for).
cmake --build "$build" --target matc_table_study >/dev/null
"$root/tests/scripts/check_docs_block.sh" --update "$root/docs/accuracy.md" table-study \
  "$build/bench/matc_table_study"
