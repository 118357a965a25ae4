#!/usr/bin/env bash
# Installs every Debian 12 package matc needs to build, test and benchmark (chromium: the report
# test opens `matc report` in it, headless; pybind11, numpy, pytest and matplotlib: the Python
# module, its tests and examples), and the npm validators the tests use (tests/js,
# pinned by its package-lock.json).
# Idempotent; safe to run as root on a fresh machine. Waits for the dpkg lock
# instead of failing when another apt process is running.
set -euo pipefail

packages=(
  cmake ninja-build g++ pkg-config clang-format
  glslang-dev glslang-tools spirv-tools spirv-headers spirv-cross libspirv-cross-c-shared-dev
  nlohmann-json3-dev libeigen3-dev libcli11-dev libfmt-dev libxxhash-dev
  libvulkan-dev mesa-vulkan-drivers vulkan-validationlayers libstb-dev libopenexr-dev
  libpugixml-dev librapidxml-dev libfast-float-dev libtinygltf-dev emscripten
  clang libclang-rt-14-dev
  chromium fonts-dejavu-core
  bazel-bootstrap nginx
  googletest libgtest-dev libgmock-dev libbenchmark-dev
  python3 python3-dev pybind11-dev python3-numpy python3-pytest python3-matplotlib python3-hypothesis
)

if [ "$(id -u)" -ne 0 ]; then
  echo "install-deps.sh: must run as root (apt-get install)" >&2
  exit 1
fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
# Node.js runs the independent checks (tests/js: JSON Schema, containers, WGSL on Dawn).
command -v npm >/dev/null 2>&1 || missing+=(nodejs npm)

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps.sh: all Debian packages already installed"
else
  echo "install-deps.sh: installing ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get -o DPkg::Lock::Timeout=600 update -qq
  apt-get -o DPkg::Lock::Timeout=600 install -y -qq --no-install-recommends "${missing[@]}"
fi

# The independent validators the tests use (Ajv, ktx-parse, parse-dds, webgpu), pinned by
# tests/js/package-lock.json; reinstalled when missing or out of date.
repo=$(cd "$(dirname "$0")/.." && pwd)
if ! npm ls --prefix "$repo/tests/js" >/dev/null 2>&1; then
  npm ci --prefix "$repo/tests/js" --no-audit --no-fund --loglevel=error
fi
