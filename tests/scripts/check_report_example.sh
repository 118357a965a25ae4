#!/usr/bin/env bash
# docs/images/report/ holds what `matc report` writes for the talk's Figure 2 material and for
# beryllium; fails when the committed plots differ from what matc writes today.
#   check_report_example.sh [--update] MATC REPO_ROOT
set -euo pipefail
update=0
if [ "${1:-}" = "--update" ]; then update=1; shift; fi
matc=${1:?usage: check_report_example.sh [--update] MATC REPO_ROOT}
root=${2:?missing REPO_ROOT}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$matc" report -o "$work" "$root/examples/materials/figure2_edge_tint.json" \
  "$root/examples/materials/beryllium.json" 2>/dev/null
committed="$root/docs/images/report"
status=0
for file in figure2_edge_tint.svg beryllium.svg; do
  if cmp -s "$work/$file" "$committed/$file"; then
    echo "$file is current"
  elif [ "$update" = 1 ]; then
    mkdir -p "$committed"
    cp "$work/$file" "$committed/$file"
    echo "$file updated"
  else
    echo "$committed/$file is stale: run tests/scripts/check_report_example.sh --update build/matc ."
    status=1
  fi
done
exit $status
