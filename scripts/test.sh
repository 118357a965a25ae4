#!/usr/bin/env bash
# Everything scripts/build.sh does, with warnings as errors, then the whole test suite, then the
# suite again under sanitizers with a short fuzzing run (scripts/test-sanitized.sh).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"

MATC_CMAKE_ARGS="-DMATC_WERROR=ON ${MATC_CMAKE_ARGS:-}" bash scripts/build.sh
ctest --test-dir build --output-on-failure --parallel "$(nproc)"
# Once more under AddressSanitizer and UndefinedBehaviorSanitizer, then a minute of fuzzing
# (MATC_SKIP_SANITIZED=1 skips this locally; CI always runs it).
if [ "${MATC_SKIP_SANITIZED:-0}" != 1 ] || [ "${CI:-}" = true ]; then
  bash scripts/test-sanitized.sh
fi
