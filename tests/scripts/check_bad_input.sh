#!/usr/bin/env bash
# One case of the bad-input catalogue (tests/data/bad_inputs/README.md): runs matc on it in a scratch
# directory and checks the exit status, that every expected line appears on standard error, and
# that a failed run wrote nothing.
#   check_bad_input.sh MATC CATALOGUE_DIR CASE
set -euo pipefail
matc=$(realpath "$1")
catalogue=$(cd "$2" && pwd)
case=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp -r "$catalogue"/. "$work/"  # cases may name each other's files (spectral CSVs, a second file)
cd "$work"
rm -f ./*.expected
[ -f "$case.setup" ] && bash -e "$case.setup"  # a setup that fails fails the case
if [ -f "$case.args" ]; then read -r -a args <"$case.args"; else args=(-o out "$case.json"); fi
status=0
"$matc" -q "${args[@]}" 2>stderr >/dev/null || status=$?

expected_file="$catalogue/$case.expected"
expected_status=$(sed -n '1s/^exit //p' "$expected_file")
failed=0
if [ "$status" != "$expected_status" ]; then
  echo "exit status $status, expected $expected_status"
  failed=1
fi
while IFS= read -r line; do
  grep -qF -- "$line" stderr || { echo "missing on stderr: $line"; failed=1; }
done < <(tail -n +2 "$expected_file")
if [ "$status" != 0 ] && [ -d out ] && [ -n "$(ls -A out)" ]; then
  echo "a failed run wrote: $(ls out)"
  failed=1
fi
if [ "$failed" != 0 ]; then
  echo "--- stderr:"
  cat stderr
  exit 1
fi
echo "$case: as expected"
