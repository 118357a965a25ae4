#!/usr/bin/env bash
# Batch throughput: N generated artistic materials (default 1000) compiled with every output at
# -j 1 and -j 2, beside the glslangValidator CLI compiling the same emitted GLSL and HLSL one file
# at a time (what a user would script without matc's in-process compile). Also peak memory at
# N/10 and N materials. Prints the Markdown table of docs/performance.md.
#   bench/batch-throughput.sh [BUILD_DIR] [N]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
count=${2:-1000}
matc=$build/matc
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# shellcheck source=bench/generated-materials.sh
source "$root/bench/generated-materials.sh"

# Seconds, peak resident memory (MiB) and CPU seconds (user + system, and user alone) of a
# command writing into a fresh output directory: the least of three runs each, since creating
# thousands of files on a shared disk varies by 2-3x from run to run (and so does the system time
# the file system takes; the user time varies little).
least() {  # current_least candidate
  if [ -z "$1" ] || awk -v a="$2" -v b="$1" 'BEGIN { exit !(a < b) }'; then echo "$2"; else echo "$1"; fi
}
measure() {  # label output_directory command...
  local label=$1 output=$2 best="" best_kilobytes=0 best_cpu="" best_user=""
  shift 2
  for _ in 1 2 3; do
    rm -rf "$output"
    /usr/bin/time -f "%e %M %U %S" -o "$work/time" "$@" >/dev/null 2>&1
    read -r seconds kilobytes user system <"$work/time"
    cpu=$(awk -v u="$user" -v s="$system" 'BEGIN { printf("%.2f", u + s) }')
    best=$(least "$best" "$seconds")
    best_cpu=$(least "$best_cpu" "$cpu")
    best_user=$(least "$best_user" "$user")
    best_kilobytes=$((kilobytes > best_kilobytes ? kilobytes : best_kilobytes))
  done
  echo "$label $best $((best_kilobytes / 1024)) $best_cpu $best_user"
}

generate_materials "$work/materials" "$count"
generate_materials "$work/small" $((count / 10))
MIXED=1 generate_materials "$work/mixed" "$count"
"$matc" -q -o "$work/warm" "$work/small/m000000.json"  # page in the binary once

j1=$(measure j1 "$work/out1" "$matc" -q -j 1 -o "$work/out1" "$work"/materials/*.json)
j2=$(measure j2 "$work/out2" "$matc" -q -j 2 -o "$work/out2" "$work"/materials/*.json)
auto=$(measure auto "$work/out5" "$matc" -q -j 2 -o "$work/out5" "$work"/mixed/*.json)
powers=$(measure powers "$work/out6" "$matc" -q -j 2 --basis powers -o "$work/out6" "$work"/materials/*.json)
small=$(measure small "$work/out3" "$matc" -q -j 2 -o "$work/out3" "$work"/small/*.json)
single=$(measure single "$work/out4" "$matc" -q -j 1 -o "$work/out4" "$work/small/m000001.json")

# The CLI baseline: per material, a GLSL and an HLSL compile of the shared library plus its
# snippet to SPIR-V, one glslangValidator process each; over the first tenth of the materials
# (each process costs the same, about 0.1 s of start-up, so the rate does not depend on how many).
cli() {
  cd "$work/out1"
  for snippet in $(ls m*.glsl | head -n "$baseline_count"); do
    name=${snippet%.glsl}
    { echo "#version 450"; cat matc_fresnel.glsl "$snippet"
      echo "layout(local_size_x = 64) in; void main() {}"; } >"$work/$name.comp"
    glslangValidator -V --target-env vulkan1.1 "$work/$name.comp" -o "$work/$name.comp.spv"
    { cat matc_fresnel.hlsl "$name.hlsl"; echo "[numthreads(64, 1, 1)] void main() {}"; } \
      >"$work/$name.hlsl"
    glslangValidator -V -D -e main -S comp --target-env vulkan1.1 "$work/$name.hlsl" \
      -o "$work/$name.hlsl.spv"
  done
}
baseline_count=$((count / 10))
export -f cli
export work baseline_count
baseline=$(measure cli "$work/unused" bash -c cli)

# What the disk alone costs: as many files as the -j 2 run writes (same sizes), each written to a
# temporary and renamed into place as matc does, by one perl process.
files=$(find "$work/out2" -type f | wc -l)
disk() {
  mkdir -p "$work/disk"
  perl -e 'my ($dir, @sizes) = @ARGV; my $i = 0;
    for my $size (@sizes) { my $f = "$dir/f" . $i++; open(my $h, ">", "$f.tmp") or die;
      print $h "x" x $size; close($h); rename("$f.tmp", $f) or die; }' \
    "$work/disk" $(find "$work/out2" -type f -printf "%s ")
}
export -f disk
disk_only=$(measure disk "$work/disk" bash -c disk)

read -r _ j1_s j1_mb j1_cpu j1_user <<<"$j1"
read -r _ j2_s j2_mb j2_cpu j2_user <<<"$j2"
read -r _ small_s small_mb small_cpu small_user <<<"$small"
read -r _ auto_s auto_mb auto_cpu auto_user <<<"$auto"
read -r _ powers_s powers_mb powers_cpu powers_user <<<"$powers"
read -r _ single_s single_mb single_cpu single_user <<<"$single"
read -r _ cli_s _ <<<"$baseline"
read -r _ disk_s _ <<<"$disk_only"
rate() { awk -v n="$1" -v s="$2" 'BEGIN { printf("%.0f", n / s) }'; }
echo "Measured on $(nproc) CPU(s), $count generated artistic materials, every output (GLSL, HLSL,"
echo "SPIR-V, C header, JSON, the table (a 128x128 layer per basis), the manifest); the least of three"
echo "runs each:"
echo
echo "| run | time (s) | CPU, user + system (s) | of it user (s) | materials/s | peak memory (MiB) |"
echo "|---|---:|---:|---:|---:|---:|"
echo "| \`matc -j 1\` | $j1_s | $j1_cpu | $j1_user | $(rate "$count" "$j1_s") | $j1_mb |"
echo "| \`matc -j 2\` | $j2_s | $j2_cpu | $j2_user | $(rate "$count" "$j2_s") | $j2_mb |"
echo "| \`matc -j 2\`, half of them F82-tint looks (each its basis: \`f82\` for those, \`powers\` for the rest) | $auto_s | $auto_cpu | $auto_user | $(rate "$count" "$auto_s") | $auto_mb |"
echo "| \`matc -j 2 --basis powers\` (one basis, the table's one layer) | $powers_s | $powers_cpu | $powers_user | $(rate "$count" "$powers_s") | $powers_mb |"
echo "| \`matc -j 2\`, $((count / 10)) materials | $small_s | $small_cpu | $small_user | $(rate $((count / 10)) "$small_s") | $small_mb |"
echo "| \`matc\`, one material (process start, table bake, compile) | $single_s | $single_cpu | $single_user | $(rate 1 "$single_s") | $single_mb |"
echo "| writing the -j 2 run's $files files alone (perl: write a temporary, rename), no compile | $disk_s | - | - | - | - |"
echo "| \`glslangValidator\`, GLSL + HLSL, one process per file (SPIR-V only), $baseline_count materials | $cli_s | - | - | $(rate "$baseline_count" "$cli_s") | - |"
echo
ratio=$(awk -v n="$count" -v s="$j2_s" -v m="$baseline_count" -v c="$cli_s" \
  'BEGIN { printf("%.0f", (n / s) / (m / c)) }')
echo "\`matc -j 2\` has ${ratio}x the CLI loop's throughput in materials per second, while also"
echo "fitting, baking, optimising, validating and writing every output."
