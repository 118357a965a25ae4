#!/usr/bin/env bash
# A face (the CLI, the Python module, the WebAssembly binding) includes libmatc's public API
# (matc/matc.h, matc/api/*; the runtime's headers and matc/version.h are public too) and nothing
# else of the library (docs/architecture.md): no module header ("<module>/x.h", compiler/src) and
# no other "matc/..." header. A face's own headers sit beside its sources, without a folder.
#   check_faces.sh REPO_ROOT
set -euo pipefail
root=${1:?usage: check_faces.sh REPO_ROOT}
cd "$root"

problems=0
checked=0
reach_of() {  # folder: "file: header" for each quoted include with a folder outside the public API
  find "$1" -type f \( -name '*.cpp' -o -name '*.h' \) -print0 | xargs -0 -r grep -H '^#include "[^"]*/' |
    sed 's/^\([^:]*\):#include "\([^"]*\)".*/\1: \2/' |
    grep -v -e ': matc/matc\.h$' -e ': matc/api/' -e ': matc/runtime/' -e ': matc/version\.h$' |
    LC_ALL=C sort -u || true
}
for folder in compiler/cli python/src js/src; do
  files=$(find "$folder" -type f \( -name '*.cpp' -o -name '*.h' \) | wc -l)
  if [ "$files" -eq 0 ]; then
    echo "$folder: no sources (a check that reads nothing checks nothing)"
    problems=$((problems + 1))
    continue
  fi
  checked=$((checked + files))
  while IFS= read -r reach; do
    echo "$folder: ${reach%%: *} includes \"${reach#*: }\", not the public API; use matc/matc.h" \
         "and matc/api/, or add what the face needs to them"
    problems=$((problems + 1))
  done < <(reach_of "$folder")
done
if [ "$problems" -ne 0 ]; then
  echo "check_faces: $problems problem(s)"
  exit 1
fi
echo "check_faces: $checked files of 3 faces (CLI, Python, WebAssembly) include the public API only"
