#!/usr/bin/env bash
# Everything scripts/build.sh does, with warnings as errors, then the whole test suite.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"

MATC_CMAKE_ARGS="-DMATC_WERROR=ON ${MATC_CMAKE_ARGS:-}" bash scripts/build.sh
ctest --test-dir build --output-on-failure --parallel "$(nproc)"
