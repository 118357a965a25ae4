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

# The module a file belongs to, into $from; for a generated source, that of the header it
# implements.
module_of_file() {
  case $1 in
    compiler/cli/*) from=cli ;;
    compiler/src/generated/*)
      from=$(grep -m1 -o '#include "[a-z_]*/' "$1" | sed 's/#include "//; s|/$||') ;;
    compiler/src/*/*) from=${1#compiler/src/}; from=${from%%/*} ;;
    compiler/include/matc/api/*) from=api ;;
    compiler/include/matc/matc.h) from=api ;;
    compiler/include/matc/*) from=base ;;  # version.h.in
    runtime/include/matc/*/*) from=${1#runtime/include/matc/}; from=${from%%/*} ;;
    runtime/src/vulkan/*) from=vulkan ;;
    runtime/src/*) from=runtime ;;
    *) from=unknown ;;
  esac
}

# The module an include names, into $to (no subshell: it runs once per include): "matc/api/..."
# or "matc/runtime/...", "matc/version.h" (base), a module's header by its path under compiler/src
# ("<module>/x.h"), or one beside the including file.
module_of_include() {
  local include=$1 including_module=$2
  case $include in
    matc/version.h) to=base ;;
    matc/matc.h) to=api ;;
    matc/*/*) include=${include#matc/}; to=${include%%/*} ;;
    */*) to=${include%%/*} ;;
    *) to=$including_module ;;
  esac
}

declare -A layer_of
for entry in $layers; do
  layer_of[${entry%%:*}]=${entry#*:}
done

problems=0
checked=0
files=0
mapfile -t sources < <(for tree in compiler runtime; do
  [ ! -d "$tree" ] || find "$tree" -type f \( -name '*.h' -o -name '*.cpp' -o -name '*.in' \)
done | LC_ALL=C sort)
# Every quoted include of every file at once, "file:line:include" (one grep, not one per file).
declare -A includes_of
if [ "${#sources[@]}" -gt 0 ]; then
  while IFS=: read -r file line include; do
    includes_of[$file]+="$line:$include"$'\n'
  done < <(grep -Hn '^#include "' "${sources[@]}" | sed 's/^\([^:]*\):\([0-9]*\):#include "\([^"]*\)".*/\1:\2:\3/')
fi
for file in "${sources[@]}"; do
  module_of_file "$file"
  from_layer=${layer_of[$from]:-}
  if [ -z "$from_layer" ]; then
    echo "$file: module '$from' has no layer (add it to tests/scripts/check_layers.sh and docs/architecture.md)"
    problems=$((problems + 1))
    continue
  fi
  while IFS=: read -r line include; do
    [ -n "$line" ] || continue
    checked=$((checked + 1))
    module_of_include "$include" "$from"
    [ "$to" = "$from" ] && continue
    to_layer=${layer_of[$to]:-}
    if [ -z "$to_layer" ]; then
      echo "$file:$line: includes \"$include\" of unknown module '$to'"
      problems=$((problems + 1))
    elif [ "$to_layer" -ge "$from_layer" ]; then
      echo "$file:$line: $from (layer $from_layer) includes \"$include\" of $to (layer $to_layer)"
      problems=$((problems + 1))
    fi
  done <<<"${includes_of[$file]:-}"
  files=$((files + 1))
done

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
