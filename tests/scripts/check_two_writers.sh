#!/usr/bin/env bash
# Two matc processes writing one output folder at once, one of them in a pid namespace of its
# own (as in a container or a build sandbox, where the other's process ids name nothing): neither
# may lose a file or leave a temporary, and the files both write (the shared tables) hold the
# bytes a lone run writes. matc's writers once swept temporaries whose process id looked dead,
# which removed the other writer's files mid-write (docs/reliability.md).
#   check_two_writers.sh MATC
set -euo pipefail
matc=$(realpath "$1")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
# The check must see what it checks: without a pid namespace it fails rather than pass vacuously.
unshare --pid --fork --kill-child true ||
  { echo "unshare --pid cannot make a pid namespace here (it needs root)"; exit 1; }

mkdir m
for set in a b; do
  for i in $(seq -w 0 149); do
    printf '{"name": "%s%s", "ior": {"n": %s, "k": 3}}\n' "$set" "$i" "0.2$i" >"m/$set$i.json"
  done
done
"$matc" -q -o alone m/a000.json
expected_shared=$(cd alone && sha256sum matc_lut.ktx2 matc_fresnel.glsl matc_coefficient_table.ktx2)

for round in 1 2 3; do
  out="out$round"
  # The first writer runs outside; the second starts while it writes, inside a new pid namespace,
  # as a child of a shell (so its process id there is a small number, not 1).
  "$matc" -q -j 2 -o "$out" m/a*.json 2>a.err &
  first=$!
  sleep 0.05
  unshare --pid --fork --kill-child sh -c "true & wait; \"$matc\" -q -j 2 -o \"$out\" m/b*.json" \
    2>b.err &
  second=$!
  status=0
  wait "$first" || status=$?
  [ "$status" = 0 ] || { echo "round $round: the first writer failed ($status):"; cat a.err; exit 1; }
  wait "$second" || status=$?
  [ "$status" = 0 ] || { echo "round $round: the namespaced writer failed ($status):"; cat b.err; exit 1; }
  for set in a b; do
    for i in $(seq -w 0 149); do
      for extension in json glsl hlsl wgsl spv h; do
        [ -s "$out/$set$i.$extension" ] || { echo "round $round: $out/$set$i.$extension is missing"; exit 1; }
      done
    done
  done
  leftovers=$(find "$out" -name '.*.matc-*.tmp' | wc -l)
  [ "$leftovers" = 0 ] || { echo "round $round: $leftovers temporaries left"; exit 1; }
  [ "$(cd "$out" && sha256sum matc_lut.ktx2 matc_fresnel.glsl matc_coefficient_table.ktx2)" = "$expected_shared" ] ||
    { echo "round $round: the shared tables differ from a lone run's"; exit 1; }
done
echo "two writers, one in its own pid namespace: 3 rounds, 1,800 material files each, none lost"
