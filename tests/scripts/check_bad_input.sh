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
trap 'rm -rf "$work" "$work.before" "$work.after"' EXIT
cp -r "$catalogue"/. "$work/"  # cases may name each other's files (spectral CSVs, a second file)
cd "$work"
rm -f ./*.expected
[ -f "$case.setup" ] && bash -e "$case.setup"  # a setup that fails fails the case
if [ -f "$case.args" ]; then read -r -a args <"$case.args"; else args=(-o out "$case.json"); fi
for i in "${!args[@]}"; do [ "${args[$i]}" != "''" ] || args[$i]=""; done  # '' is an empty argument
# Every file but matc's outputs, with its hash: none may be removed or changed by the run.
snapshot() { find . -path ./out -prune -o -type f ! -name stderr -print0 | xargs -0 -r sha256sum | LC_ALL=C sort; }
snapshot >"$work.before"
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
# One diagnostic per line, nothing for a terminal to act on: no control byte but the line feed.
if LC_ALL=C grep -q $'[\x01-\x09\x0b-\x1f\x7f]' stderr || [ "$(tr -d '\000' <stderr | wc -c)" != "$(wc -c <stderr)" ]; then
  echo "a control byte on stderr:"
  LC_ALL=C grep -n $'[\x01-\x09\x0b-\x1f\x7f]' stderr | cat -A | head -5
  failed=1
fi
# <case>.absent: lines no line of stderr may start with (a diagnostic forged by input text).
if [ -f "$catalogue/$case.absent" ]; then
  while IFS= read -r line; do
    if grep -q -F -x -- "$line" <(cut -c1-${#line} stderr); then
      echo "a line starts with: $line"
      failed=1
    fi
  done <"$catalogue/$case.absent"
fi
snapshot >"$work.after"
if ! diff -q "$work.before" "$work.after" >/dev/null; then
  if [ -n "$(LC_ALL=C comm -23 "$work.before" "$work.after")" ]; then
    echo "removed or changed a file it did not write:"
    LC_ALL=C comm -23 "$work.before" "$work.after"
    failed=1
  fi
fi
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
