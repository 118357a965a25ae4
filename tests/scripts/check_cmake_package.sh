#!/usr/bin/env bash
# The installed CMake package works for a consumer: install this build (its headers the public API
# alone), build examples/engine against it (matc_add_materials, generated headers, SPIR-V linking, libmatc from memory), run it;
# then a second build is a no-op and touching a material reruns matc.
#   check_cmake_package.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build=$1
source=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install "$build" --prefix "$work/prefix" >/dev/null
# The package carries the public API alone: matc/matc.h, matc/api/, matc/version.h and the
# runtime's headers (matc/runtime/, matc/vulkan/); the modules' headers stay in the source tree.
beyond=$(cd "$work/prefix/include/matc" && find . -type f | LC_ALL=C sort |
  grep -v -e '^\./matc\.h$' -e '^\./version\.h$' -e '^\./api/' -e '^\./runtime/' -e '^\./vulkan/' || true)
[ -z "$beyond" ] || { echo "the package installs headers beyond the public API:"; echo "$beyond"; exit 1; }
[ -f "$work/prefix/include/matc/api/compiled_material.h" ] || { echo "the public API is not installed"; exit 1; }
# The installed Python module imports from the prefix alone (no build tree on its path).
python_dir=$(sed -n 's/^MATC_PYTHON_INSTALL_DIR:STRING=//p' "$build/CMakeCache.txt")
if [ -n "$python_dir" ]; then
  python=$(sed -n 's/^MATC_PYTHON_EXECUTABLE:INTERNAL=//p' "$build/CMakeCache.txt")
  (cd "$work" && PYTHONPATH="$work/prefix/$python_dir" "$python" -c \
    "import matc, sys; assert matc.__file__.startswith(sys.argv[1]), matc.__file__; print(matc.compile({'name': 'gold', 'ior': {'n': 0.2, 'k': 3.4}}).coefficients.shape)" \
    "$work/prefix") | grep -q "(3, 4)" || { echo "the installed Python module does not import"; exit 1; }
fi
mkdir -p "$work/engine-src"
cp -r "$source/examples/engine/." "$work/engine-src/"
mkdir -p "$work/materials" "$work/textured"  # the example names ../materials, ../textured
cp "$source/examples/materials/gold.json" "$source/examples/materials/figure2_edge_tint.json" \
  "$work/materials/"
cp "$source/examples/textured/make_maps.cpp" "$source/examples/textured/inlaid_metals.json" \
  "$work/textured/"
cmake -S "$work/engine-src" -B "$work/engine" -G Ninja -DCMAKE_PREFIX_PATH="$work/prefix" >/dev/null
cmake --build "$work/engine" >/dev/null
"$work/engine/engine"
# The cooker (libmatc's batch compile) writes the bytes the installed matc writes for the same
# materials; its in-memory material is a file for matc, under the name the cooker gives it.
(cd "$work" && engine/cooker cooked materials/gold.json materials/figure2_edge_tint.json >/dev/null)
mkdir -p "$work/generated"
# (without a final newline: the inputs hash covers the text's bytes)
printf '%s' "$(sed -n 's/^      R"(\(.*\))"));$/\1/p' "$source/examples/engine/cooker.cpp")" \
  >"$work/generated/brushed_brass.json"
(cd "$work" && prefix/bin/matc -q -o by-matc materials/gold.json materials/figure2_edge_tint.json \
  generated/brushed_brass.json)
diff -r -x cook.d "$work/cooked" "$work/by-matc" ||
  { echo "the cooker's files differ from matc's"; exit 1; }
grep -q "gold.json" "$work/cooked/cook.d" || { echo "the cooker's depfile lacks its inputs"; exit 1; }
# Ninja's whole output first: `ninja | grep -q` fails under pipefail when grep stops reading early
# (gold's out-of-gamut note follows the line it matches).
ran() { local out; out=$(ninja -C "$work/engine" "${@:2}"); grep -q "$1" <<<"$out"; }
ran "no work to do" -n || { echo "second build is not a no-op"; exit 1; }
sleep 1
touch "$work/materials/gold.json"
ran "matc: compiling" || { echo "touching a material did not rerun matc"; exit 1; }
sleep 1
touch "$work/engine/maps/inlaid_metals_g.png"
ran "matc bake: inlaid_metals" ||
  { echo "touching a map did not rebake its asset"; exit 1; }
echo "cmake package: consumer built, ran, its cooker wrote what matc writes, and it rebuilds only when its materials or maps change"
