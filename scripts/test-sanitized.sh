#!/usr/bin/env bash
# A short fuzzing run, then the test suite again under AddressSanitizer and
# UndefinedBehaviorSanitizer (clang, libFuzzer coverage instrumentation included). scripts/test.sh
# (CI) runs it last.
#   scripts/test-sanitized.sh [FUZZ_SECONDS]   (default 60)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
fuzz_seconds=${1:-60}

# No Python module here: a sanitized extension needs the sanitizer runtimes preloaded into the
# interpreter; the module's C++ is libmatc's, which the sanitized suite covers, and its own
# tests (with their fuzz pass) run in the plain build. No benchmarks and studies either (bench/,
# a tenth of this build's compile work): their checks print docs tables and cost figures, which
# the plain build checks once; the library code they call runs here through the unit tests. No
# comparison renders (examples/render, another tenth): their checks compare images' errors, which
# the plain build checks; the library and the Vulkan executor they drive run here through
# DeviceValidation, the executor's tests and `matc validate`.
CC=clang CXX=clang++ cmake -S . -B build-fuzz -G Ninja -DMATC_BUILD_FUZZERS=ON \
  -DMATC_SANITIZE=address,undefined,fuzzer-no-link -DMATC_BUILD_PYTHON=OFF -DMATC_BUILD_WASM=OFF \
  -DMATC_BUILD_BENCH=OFF -DMATC_BUILD_RENDERS=OFF >/dev/null
cmake --build build-fuzz

# libFuzzer writes crash, leak and slow-unit inputs to the working directory unless told where:
# into the (ignored) build folder, never the source tree.
artifacts=build-fuzz/fuzz-artifacts/
mkdir -p "$artifacts"
corpus=$(mktemp -d)
trap 'rm -rf "$corpus"' EXIT
build-fuzz/tests/fuzz/matc_material_fuzzer -artifact_prefix="$artifacts" -max_total_time="$fuzz_seconds" -max_len=4096 \
  -dict=tests/fuzz/material.dict -print_final_stats=1 "$corpus" tests/fuzz/corpus 2>&1 | tail -n 20
# The textured-metal inputs (option parser, coefficient-table path): a quarter of that time.
table_corpus=$(mktemp -d)
trap 'rm -rf "$corpus" "$table_corpus"' EXIT
build-fuzz/tests/fuzz/matc_coefficient_table_fuzzer -artifact_prefix="$artifacts" -max_total_time="$((fuzz_seconds / 4 + 1))" \
  -max_len=256 -print_final_stats=1 "$table_corpus" tests/fuzz/corpus_coefficient_table 2>&1 |
  tail -n 8
# matc eval's --quad-light parser and the area-light integrals on what it accepts: 10 s.
light_corpus=$(mktemp -d)
trap 'rm -rf "$corpus" "$table_corpus" "$light_corpus"' EXIT
build-fuzz/tests/fuzz/matc_polygon_light_fuzzer -artifact_prefix="$artifacts" -max_total_time=10 -max_len=256 \
  -print_final_stats=1 "$light_corpus" tests/fuzz/corpus_polygon_light 2>&1 | tail -n 8
# The MaterialX importer (documents re-read and compiled): 15 s.
mtlx_corpus=$(mktemp -d)
trap 'rm -rf "$corpus" "$table_corpus" "$light_corpus" "$mtlx_corpus"' EXIT
build-fuzz/tests/fuzz/matc_materialx_fuzzer -artifact_prefix="$artifacts" -max_total_time=15 -max_len=4096 \
  -dict=tests/fuzz/materialx.dict -print_final_stats=1 "$mtlx_corpus" tests/fuzz/corpus_materialx 2>&1 | tail -n 8
# MaterialX's two XML readers, pugixml (native) and rapidxml (WebAssembly), against each other on
# the same seeds (its inputs go to the importer's scratch corpus): 10 s.
build-fuzz/tests/fuzz/matc_xml_tree_fuzzer -artifact_prefix="$artifacts" -max_total_time=10 -max_len=4096 \
  -dict=tests/fuzz/materialx.dict -print_final_stats=1 "$mtlx_corpus" tests/fuzz/corpus_materialx 2>&1 | tail -n 8
# The glTF importer (assets re-read and compiled; first byte: .glb when odd): 10 s.
gltf_corpus=$(mktemp -d)
trap 'rm -rf "$corpus" "$table_corpus" "$light_corpus" "$mtlx_corpus" "$gltf_corpus"' EXIT
build-fuzz/tests/fuzz/matc_gltf_fuzzer -artifact_prefix="$artifacts" -max_total_time=10 -max_len=4096 \
  -dict=tests/fuzz/gltf.dict -print_final_stats=1 "$gltf_corpus" tests/fuzz/corpus_gltf 2>&1 | tail -n 8
# The public API as the faces call it (options by name, any document, curves, texts): 10 s.
# Seeds: the material corpus behind an options byte (defaults; the paper basis in ACEScg).
api_corpus=$(mktemp -d)
trap 'rm -rf "$corpus" "$table_corpus" "$light_corpus" "$mtlx_corpus" "$gltf_corpus" "$api_corpus"' EXIT
for seed in tests/fuzz/corpus/*; do
  for options in 000 005 200; do  # \200: the numbers and SPIR-V calls too
    { printf "\\$options"; cat "$seed"; } >"$api_corpus/$(basename "$seed").$options"
  done
done
build-fuzz/tests/fuzz/matc_public_api_fuzzer -artifact_prefix="$artifacts" -max_total_time=10 -max_len=4096 \
  -dict=tests/fuzz/material.dict -print_final_stats=1 "$api_corpus" 2>&1 | tail -n 8
# matc bake's image readers and asset parser: seeds written by matc_catalogue_images (no image is
# stored in the repository), each once per mode (first byte: sRGB, linear, asset text); 15 s.
image_corpus=$(mktemp -d)
image_seeds=$(mktemp -d)
trap 'rm -rf "$corpus" "$table_corpus" "$light_corpus" "$mtlx_corpus" "$gltf_corpus" "$api_corpus" "$image_corpus" "$image_seeds"' EXIT
build-fuzz/tests/matc_catalogue_images "$image_seeds"
for seed in "$image_seeds"/*; do
  for mode in 0 1; do
    { printf "\\$(printf %03o "$mode")"; cat "$seed"; } >"$image_corpus/$(basename "$seed").$mode"
  done
done
printf '\002{"name": "brass", "artistic": {"reflectivity": {"file": "r.exr", "encoding": "linear"}, "edge_tint": [0.5, 0.6, 0.7]}}' >"$image_corpus/asset.2"
build-fuzz/tests/fuzz/matc_image_map_fuzzer -artifact_prefix="$artifacts" -max_total_time=15 -max_len=4096 -rss_limit_mb=4096 \
  -print_final_stats=1 "$image_corpus" 2>&1 | tail -n 8

# Mesa's drivers (lavapipe, and RADV for gpu_cost), LLVM and the Vulkan loader keep allocations
# until exit, and lavapipe's JIT-compiled shaders allocate from code LeakSanitizer cannot name:
# tests that run Vulkan are checked by AddressSanitizer and UBSan but without leak detection;
# every other test with it.
export LSAN_OPTIONS="suppressions=$root/tests/fuzz/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="print_stacktrace=1"
vulkan_tests="Vulkan|DeviceValidation|validate_on_device|Validat"
# matc validate per example material runs one code path with other numbers (10 s each here): the
# sanitized run keeps a measured bare metal, a coated one, the embedded table and MaterialX, and
# leaves the rest to the plain build.
validate_once="validate_on_device_(aluminium|aluminium_brushed_openpbr|beryllium|chromium|figure2_edge_tint|gold|gold_measured_file|gold_rgb_ior|iron|silver|tinted_steel|titanium|f82_basis|acescg_desaturated)$"
# The package test installs instrumented static libraries, which a plain consumer cannot link.
# The per-material Ninja test checks build edges, not memory, the two-writer test files between
# processes, and output_hashes checks bytes
# the plain build's run already compares (the same code paths run in MatcCli under sanitizers):
# once, unsanitised, is their budget. So is it for the browser and Dawn checks (pages in
# Chromium, WGSL on Dawn, three.js and Babylon.js against the CPU runtime, in a one-basis build and
# a per-material one): their time goes to the
# uninstrumented browser and to `matc eval` runs some 40 times slower under the sanitizers (445 s
# of the sanitized run's 1150 s of test time before they left it), while the matc code they call
# runs sanitized in MatcCli and the bad-input catalogue.
browser_tests="_in_browser|_against_reference|_on_dawn|_engine_one_basis"
# The docs blocks print the main suite's studies again (150 s of test time here, accuracy's alone
# 53 s): the text is checked once, in the plain build, and the studies' code runs under the
# sanitizers through their unit tests (accuracy_test, coat_test, coated_compile_test, ...). So do
# the checks of the sources rather than of matc (formatting, the layers' includes) and Bazel's
# remote cache, which, like the Ninja test, checks build edges.
once_only="_docs_current|_readme_current|clang_format|layers_|bazel_remote_cache"
# The checked-in tables' regeneration (the coefficient and LTC tables rebuilt whole and compared
# byte for byte: 120 s of test time here) is a check of bytes, once; the fits' code runs here
# through their unit tests (CoefficientTable, ConductorSolver, LtcFit). So are the checks that
# hand matc's outputs to independent tools (Ajv on the schema, Khronos' glTF-Validator,
# glslang and spirv-val on the emitted shaders; 80 s) and Ninja's depfile edges.
once_only="$once_only|CheckedIn|RegenerationApi.MakesTheCheckedInSourcesAgain|material_schema|gltf_out_validated|emitted_shaders_independent_tools|depfile_drives_ninja"
# Three sweeps of the accuracy targets over many materials (2,200 random (r, g) through the
# coefficient table, the F82-tint materials, the measured metals under coats: 70 s of test time
# here) run code that the same suites' other tests run here on a few; the targets are numbers,
# checked once.
once_only="$once_only|CoefficientTable.MeetsTheTargetsAgainstThePerMaterialCompile|Accuracy.F82BasisFitsF82TintMaterialsWithinTheTarget|CoatedCompile.MeasuredMetalsUnderClearCoatsMeetTheTargets"
ctest --test-dir build-fuzz --output-on-failure --parallel "$(nproc)" \
  -E "cmake_package_engine_example|per_material_ninja_edges|output_hashes|two_writers_one_folder|$once_only|$browser_tests|$vulkan_tests"
ASAN_OPTIONS=detect_leaks=0 ctest --test-dir build-fuzz --output-on-failure \
  --parallel "$(nproc)" -R "$vulkan_tests" -E "$once_only|$validate_once"
