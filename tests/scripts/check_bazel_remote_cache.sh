#!/usr/bin/env bash
# bazel/matc.bzl on Debian's Bazel (bazel-bootstrap), offline, against an HTTP remote cache that
# nginx serves on 127.0.0.1 (WebDAV PUT): the examples are built from one clean output base, then
# from a second one. The second build must take every action from the cache, and both must write
# the bytes a plain matc batch writes and every file of it (less the manifest, which only a batch
# has; a filmed metal's own table included).
#   check_bazel_remote_cache.sh MATC SOURCE_DIR
set -euo pipefail
matc=$(realpath "$1")
source_dir=$(realpath "$2")
for tool in bazel nginx; do
  command -v "$tool" >/dev/null || { echo "$tool not found (scripts/install-deps.sh installs it)"; exit 1; }
done
work=$(mktemp -d)
chmod 755 "$work"  # nginx's workers (www-data) reach the cache through it
nginx_pid=""
cleanup() {
  [[ -n $nginx_pid ]] && kill "$nginx_pid" 2>/dev/null || true
  for base in "$work"/base*; do
    [[ -d $base ]] && bazel --output_base="$base" --batch shutdown >/dev/null 2>&1 || true
  done
  [[ -n ${KEEP:-} ]] || rm -rf "$work"
}
trap cleanup EXIT

# The workspace: the rules, the matc binary (an input of every action), the example materials.
workspace=$work/workspace
mkdir -p "$workspace/bazel" "$workspace/tools" "$workspace/materials"
touch "$workspace/WORKSPACE"
cp "$source_dir/bazel/matc.bzl" "$source_dir/bazel/matc_layout.bzl" "$source_dir/bazel/BUILD" "$workspace/bazel/"
cp "$matc" "$workspace/tools/matc"
echo 'exports_files(["matc"])' >"$workspace/tools/BUILD"
cp -r "$source_dir/examples/materials/." "$workspace/materials/"
{
  echo 'load("//bazel:matc.bzl", "matc_material", "matc_shared")'
  echo 'matc_shared(name = "shared", matc = "//tools:matc")'
  for file in "$workspace"/materials/*.json; do
    name=$(basename "$file" .json)
    data=""
    # Spectral files a material names (examples name them under spectra/).
    if grep -q '"file"' "$file"; then data=', data = glob(["spectra/*.csv"])'; fi
    # A filmed metal says so: its own table is then declared (Bazel cannot read the JSON).
    if grep -q '"film"' "$file"; then data="$data, film = True"; fi
    echo "matc_material(name = \"$name\", src = \"$name.json\", matc = \"//tools:matc\"$data)"
  done
} >"$workspace/materials/BUILD"
sed -i 's|matc_shared(name = "shared", matc = "//tools:matc")||' "$workspace/materials/BUILD"
echo 'load("//bazel:matc.bzl", "matc_shared")
matc_shared(name = "shared", matc = "//tools:matc")' >"$workspace/BUILD"

# nginx as a WebDAV store for Bazel's HTTP cache (shared/notes/toolchain.md has the recipe).
mkdir -p "$work/nginx/cache" "$work/nginx/body" "$work/nginx/logs"
chown -R www-data "$work/nginx/cache" "$work/nginx/body"
port=$((20000 + RANDOM % 20000))
cat >"$work/nginx/nginx.conf" <<NGINX
user www-data;
pid $work/nginx/nginx.pid;
error_log $work/nginx/logs/error.log;
events {}
http {
  access_log $work/nginx/logs/access.log;
  server {
    listen 127.0.0.1:$port;
    root $work/nginx/cache;
    client_body_temp_path $work/nginx/body;
    client_max_body_size 1g;
    location / { dav_methods PUT; create_full_put_path on; }
  }
}
NGINX
nginx -c "$work/nginx/nginx.conf" -p "$work/nginx"
for _ in $(seq 50); do [[ -s $work/nginx/nginx.pid ]] && break; sleep 0.1; done
nginx_pid=$(cat "$work/nginx/nginx.pid")

build() {  # output base: Bazel's messages go to <output base>.log, its summary line to stdout
  local status=0
  (cd "$workspace" && bazel --output_base="$1" --batch build //... \
     --remote_cache="http://127.0.0.1:$port" --noshow_progress --symlink_prefix=/ \
     >"$1.log" 2>&1) || status=$?
  if [[ $status != 0 ]] || grep -q "errors during bulk transfer" "$1.log"; then
    grep -v "linux-sandbox" "$1.log" | tail -20
    echo "FAIL: bazel build from $1 (exit $status, or the cache refused a write)"
    exit 1
  fi
  grep -o "INFO: [0-9]* processes: .*" "$1.log"
}
build "$work/base1" >/dev/null
summary=$(build "$work/base2")
echo "second build: $summary"
actions=$(ls "$workspace"/materials/*.json | wc -l)
hits=$(grep -o "[0-9]* remote cache hit" <<<"$summary" | grep -o "^[0-9]*" || echo 0)
[[ $hits -eq $((actions + 1)) ]] ||
  { echo "FAIL: $hits remote cache hits, expected $((actions + 1)) (every material and the shared files)"; exit 1; }

# Same bytes as a plain batch, from both output bases.
"$matc" -q -o "$work/batch" "$workspace"/materials/*.json 2>/dev/null
outputs=0
for base in base1 base2; do
  bin=$(ls -d "$work/$base"/execroot/__main__/bazel-out/*/bin)
  for file in "$bin"/matc/* "$bin"/materials/matc/*; do
    cmp -s "$file" "$work/batch/$(basename "$file")" ||
      { echo "FAIL: $base $(basename "$file") differs from the batch's"; exit 1; }
    outputs=$((outputs + 1))
  done
  # And every file of the batch's is among Bazel's (an undeclared one, a filmed metal's table
  # without `film = True`, would be written and left out).
  for file in "$work"/batch/*; do
    name=$(basename "$file")
    [[ $name == matc_manifest.json ]] && continue
    [[ -e $bin/matc/$name || -e $bin/materials/matc/$name ]] ||
      { echo "FAIL: $base lacks the batch's $name"; exit 1; }
  done
done
echo "Bazel + remote cache: $outputs outputs over two output bases, all the batch's bytes; second build all cache hits"
