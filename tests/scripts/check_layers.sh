#!/usr/bin/env bash
# Includes point down the layers (docs/architecture.md): a module may include itself and the
# modules of lower layers, never a module of its own layer or above. Reads every quoted #include
# of compiler/ and runtime/ (listed from the file system: a release tarball has no git) and names
# each one that points up or sideways.
#   check_layers.sh REPO_ROOT
set -euo pipefail
root=${1:?usage: check_layers.sh REPO_ROOT}
cd "$root"

# module:layer, lowest first. Same layer: independent of each other.
layers="runtime:0 base:1 vulkan:1 optics:2 formats:2 spirv:2 material:3 fit:3 basis:4 lut:4
compile:5 ltc:6 bake:6 report:6 emit:7 options:8 pipeline:8 validate:8 api:9 cli:10"

# The module a file belongs to; for a generated source, that of the header it implements.
module_of_file() {
  case $1 in
    compiler/cli/*) echo cli ;;
    compiler/src/generated/*)
      grep -m1 -o '#include "[a-z_]*/' "$1" | sed 's/#include "//; s|/$||' ;;
    compiler/src/*/*) echo "$1" | cut -d/ -f3 ;;
    compiler/include/matc/api/*) echo api ;;
    compiler/include/matc/matc.h) echo api ;;
    compiler/include/matc/*) echo base ;;  # version.h.in
    runtime/include/matc/*/*) echo "$1" | cut -d/ -f4 ;;
    runtime/src/vulkan/*) echo vulkan ;;
    runtime/src/*) echo runtime ;;
    *) echo unknown ;;
  esac
}

# The module an include names: "matc/api/..." or "matc/runtime/...", "matc/version.h" (base), a
# module's header by its path under compiler/src ("<module>/x.h"), or one beside the including file.
module_of_include() {
  local include=$1 including_module=$2
  case $include in
    matc/version.h) echo base ;;
    matc/matc.h) echo api ;;
    matc/*/*) include=${include#matc/}; echo "${include%%/*}" ;;
    */*) echo "${include%%/*}" ;;
    *) echo "$including_module" ;;
  esac
}

layer_of() {
  local entry
  for entry in $layers; do
    [ "${entry%%:*}" = "$1" ] && { echo "${entry#*:}"; return; }
  done
  echo ""
}

problems=0
checked=0
files=0
while IFS= read -r file; do
  from=$(module_of_file "$file")
  from_layer=$(layer_of "$from")
  if [ -z "$from_layer" ]; then
    echo "$file: module '$from' has no layer (add it to tests/scripts/check_layers.sh and docs/architecture.md)"
    problems=$((problems + 1))
    continue
  fi
  while IFS=: read -r line include; do
    checked=$((checked + 1))
    to=$(module_of_include "$include" "$from")
    [ "$to" = "$from" ] && continue
    to_layer=$(layer_of "$to")
    if [ -z "$to_layer" ]; then
      echo "$file:$line: includes \"$include\" of unknown module '$to'"
      problems=$((problems + 1))
    elif [ "$to_layer" -ge "$from_layer" ]; then
      echo "$file:$line: $from (layer $from_layer) includes \"$include\" of $to (layer $to_layer)"
      problems=$((problems + 1))
    fi
  done < <(grep -n '^#include "' "$file" | sed 's/^\([0-9]*\):#include "\([^"]*\)".*/\1:\2/')
  files=$((files + 1))
done < <(for tree in compiler runtime; do
  [ ! -d "$tree" ] || find "$tree" -type f \( -name '*.h' -o -name '*.cpp' -o -name '*.in' \)
done | LC_ALL=C sort)

# A check that read nothing has checked nothing: fail, do not pass.
if [ "$files" -eq 0 ] || [ "$checked" -eq 0 ]; then
  echo "check_layers: read $files files and $checked includes under $root: nothing to check"
  exit 1
fi
if [ "$problems" -gt 0 ]; then
  echo "check_layers: $problems include(s) point up or sideways"
  exit 1
fi
echo "check_layers: $checked includes of $files files point down the layers"
