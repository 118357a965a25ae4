#!/usr/bin/env bash
# A face (the CLI, the Python module, the WebAssembly binding) includes libmatc's public API
# (matc/matc.h, matc/api/*; the runtime's headers and matc/version.h are public too) and nothing
# else of the library (docs/architecture.md). The
# WebAssembly face and the Python module are held to that; the CLI still reaches into modules for
# the maintainers' `matc basis` regeneration subcommands, and
# tests/data/face_reach/cli.txt lists what it may still include: a new reach fails, and so does an
# entry no longer used (the list only shrinks as the CLI moves to the public API).
#   check_faces.sh REPO_ROOT
set -euo pipefail
root=${1:?usage: check_faces.sh REPO_ROOT}
cd "$root"

problems=0
checked=0
reach_of() {  # folder: the library headers it includes outside the public API, sorted
  find "$1" -type f \( -name '*.cpp' -o -name '*.h' \) -print0 | xargs -0 -r grep -h '^#include "matc/' |
    sed 's/^#include "\([^"]*\)".*/\1/' | grep -v -e '^matc/matc\.h$' -e '^matc/api/' -e '^matc/runtime/' -e '^matc/version\.h$' | LC_ALL=C sort -u || true
}
for face in cli:compiler/cli python:python/src js:js/src; do
  name=${face%%:*}
  folder=${face#*:}
  files=$(find "$folder" -type f \( -name '*.cpp' -o -name '*.h' \) | wc -l)
  if [ "$files" -eq 0 ]; then
    echo "$folder: no sources (a check that reads nothing checks nothing)"
    problems=$((problems + 1))
    continue
  fi
  checked=$((checked + files))
  allowed=tests/data/face_reach/$name.txt
  [ -f "$allowed" ] || allowed=/dev/null
  while IFS= read -r header; do
    echo "$folder: includes \"$header\", a module of the library; use the public API (matc/matc.h)" \
         "or add what the face needs to it"
    problems=$((problems + 1))
  done < <(LC_ALL=C comm -23 <(reach_of "$folder") <(LC_ALL=C sort -u "$allowed"))
  while IFS= read -r header; do
    echo "$allowed: \"$header\" is no longer included by $folder: remove it from the list"
    problems=$((problems + 1))
  done < <(LC_ALL=C comm -13 <(reach_of "$folder") <(LC_ALL=C sort -u "$allowed"))
done
if [ "$problems" -ne 0 ]; then
  echo "check_faces: $problems problem(s)"
  exit 1
fi
echo "check_faces: $checked files of 3 faces; the WebAssembly and Python faces include the public" \
     "API only, the CLI still $(grep -c . tests/data/face_reach/cli.txt) module headers"
