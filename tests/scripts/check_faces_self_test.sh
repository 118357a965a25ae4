#!/usr/bin/env bash
# check_faces.sh can fail: on a copy of the faces, a module header (by its path under compiler/src)
# included by the WebAssembly binding, another by the Python module and a "matc/..." header outside
# the public API by the CLI must each be reported.
#   check_faces_self_test.sh CHECK_FACES REPO_ROOT
set -euo pipefail
check=$1
root=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/compiler"
cp -r "$root/compiler/cli" "$work/compiler/"
cp -r "$root/python" "$root/js" "$work/"
bash "$check" "$work" >/dev/null || { echo "the copy fails before any change"; exit 1; }
echo '#include "compile/compile.h"' >>"$work/js/src/bindings.cpp"
echo '#include "lut/preintegrate.h"' >>"$work/python/src/module.cpp"
echo '#include "matc/no/such_header.h"' >>"$work/compiler/cli/main.cpp"
output=$(bash "$check" "$work" || true)
grep -q 'js/src: js/src/bindings.cpp includes "compile/compile.h"' <<<"$output" || { echo "missed the WebAssembly include:"; echo "$output"; exit 1; }
grep -q 'python/src: python/src/module.cpp includes "lut/preintegrate.h"' <<<"$output" || { echo "missed the Python include:"; echo "$output"; exit 1; }
grep -q 'compiler/cli: compiler/cli/main.cpp includes "matc/no/such_header.h"' <<<"$output" || { echo "missed the CLI include:"; echo "$output"; exit 1; }
echo "check_faces reports a reach from each face"
