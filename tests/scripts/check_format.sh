#!/usr/bin/env bash
# Fails when any C++ source under the repository differs from what clang-format produces.
set -euo pipefail
root=${1:?usage: check_format.sh REPO_ROOT}
cd "$root"
command -v clang-format >/dev/null || { echo "clang-format not found (scripts/install-deps.sh installs it)"; exit 1; }
mapfile -t files < <(find compiler runtime tests bench examples \( -name '*.cpp' -o -name '*.h' \) -not -path '*/node_modules/*' | sort)
clang-format --dry-run --Werror "${files[@]}"
echo "clang-format: ${#files[@]} files clean"
