#!/usr/bin/env bash
# check_layers.sh can fail: in a small tree whose optics source includes an emit header and whose
# fit header includes a sibling's, it names both and exits 1; with those lines gone it passes; a
# tree with no sources (a wrong root) fails. No git: the tree is plain files, as in a tarball.
#   check_layers_self_test.sh CHECK_LAYERS_SH
set -euo pipefail
check=${1:?usage: check_layers_self_test.sh CHECK_LAYERS_SH}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/compiler/src/optics" "$work/compiler/src/fit"
printf '#include "optics/fresnel.h"\n#include "emit/build.h"\n' \
  >"$work/compiler/src/optics/fresnel.cpp"
printf '#include "material/material.h"\n#include "matc/runtime/basis.h"\n' \
  >"$work/compiler/src/fit/accuracy.h"
if bash "$check" "$work/compiler/src" >/dev/null; then
  echo "check_layers passed a tree it read no file of"; exit 1
fi
if out=$(bash "$check" "$work"); then
  echo "check_layers passed a tree with upward includes"; exit 1
fi
grep -q 'compiler/src/optics/fresnel.cpp:2: optics (layer 2) includes "emit/build.h"' <<<"$out"
grep -q 'compiler/src/fit/accuracy.h:1: fit (layer 3) includes "material/material.h"' <<<"$out"
sed -i '2d' "$work/compiler/src/optics/fresnel.cpp"
sed -i '1d' "$work/compiler/src/fit/accuracy.h"
bash "$check" "$work" >/dev/null || { echo "check_layers failed a tree that follows the layers"; exit 1; }
echo "check_layers: names upward and sideways includes, passes a tree without them"
