#!/usr/bin/env bash
# check_faces.sh can fail: on a copy of the faces, a module include added to the WebAssembly face
# or the Python module, and an entry the CLI no longer uses, must each be reported.
#   check_faces_self_test.sh CHECK_FACES REPO_ROOT
set -euo pipefail
check=$1
root=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/compiler" "$work/tests/data"
cp -r "$root/compiler/cli" "$work/compiler/"
cp -r "$root/python" "$root/js" "$work/"
cp -r "$root/tests/data/face_reach" "$work/tests/data/"
bash "$check" "$work" >/dev/null || { echo "the copy fails before any change"; exit 1; }
echo '#include "matc/compile/compile.h"' >>"$work/js/src/bindings.cpp"
echo '#include "matc/lut/preintegrate.h"' >>"$work/python/src/module.cpp"
echo 'matc/no/such_header.h' >>"$work/tests/data/face_reach/cli.txt"
output=$(bash "$check" "$work" || true)
grep -q 'js/src: includes "matc/compile/compile.h"' <<<"$output" || { echo "missed the new include:"; echo "$output"; exit 1; }
grep -q 'python/src: includes "matc/lut/preintegrate.h"' <<<"$output" || { echo "missed the Python include:"; echo "$output"; exit 1; }
grep -q '"matc/no/such_header.h" is no longer included' <<<"$output" || { echo "missed the stale entry:"; echo "$output"; exit 1; }
echo "check_faces reports a new reach and a stale entry"
