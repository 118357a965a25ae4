#!/usr/bin/env bash
# Published numbers come from commands: compares (or with --update, replaces) the block between
#   <!-- BEGIN GENERATED: NAME --> and <!-- END GENERATED: NAME -->
# in a document with what COMMAND prints now.
#   check_docs_block.sh [--update] DOCUMENT NAME COMMAND [ARGS...]
set -euo pipefail
update=0
if [ "${1:-}" = "--update" ]; then update=1; shift; fi
document=${1:?usage: check_docs_block.sh [--update] DOCUMENT NAME COMMAND [ARGS...]}
name=${2:?missing NAME}
shift 2
[ $# -gt 0 ] || { echo "check_docs_block.sh: missing COMMAND"; exit 2; }
begin="<!-- BEGIN GENERATED: $name -->"
end="<!-- END GENERATED: $name -->"

fresh=$(mktemp)
trap 'rm -f "$fresh" "$fresh.doc"' EXIT
"$@" >"$fresh"
grep -qxF "$begin" "$document" || { echo "$document: missing line '$begin'"; exit 1; }
grep -qxF "$end" "$document" || { echo "$document: missing line '$end'"; exit 1; }

# The document with the block's body replaced by the fresh output.
awk -v begin="$begin" -v end="$end" -v fresh="$fresh" '
  $0 == begin { print; while ((getline line < fresh) > 0) print line; skipping = 1; next }
  $0 == end { skipping = 0 }
  !skipping { print }' "$document" >"$fresh.doc"

if cmp -s "$fresh.doc" "$document"; then
  echo "$document: block '$name' is current"
elif [ "$update" = 1 ]; then
  cp "$fresh.doc" "$document"
  echo "$document: block '$name' updated"
else
  echo "$document: block '$name' is stale; run bench/accuracy/update-docs.sh. Difference:"
  diff "$document" "$fresh.doc" || true
  exit 1
fi
