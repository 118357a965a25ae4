#!/usr/bin/env bash
# The README's Python quick start, as written: its shell lines from the repository root, with
# `python3` the interpreter the module was built for and build/ the build under test.
# Usage: check_python_quick_start.sh PYTHON BUILD_DIR README
set -euo pipefail
python=$1
build=$(cd "$2" && pwd)
readme=$3
lines=$(sed -n '/<!-- BEGIN PYTHON QUICK START/,/<!-- END PYTHON QUICK START -->/p' "$readme" |
  sed -n '/^```sh$/,/^```$/p' | sed '1d;$d')
[ -n "$lines" ] || { echo "FAIL: README.md has no Python quick start between its markers" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
ln -s "$build" "$work/build"
cd "$work"
out=$(sed -e "s|python3 |$python |g" <<<"$lines" | bash -euo pipefail)
echo "$out"
# The coefficients' array: three rows of four.
[ "$(grep -c '\[' <<<"$out")" -ge 3 ] || { echo "FAIL: no (3, 4) array printed" >&2; exit 1; }
