#!/usr/bin/env bash
# Everything scripts/build.sh does, with warnings as errors, then the whole test suite, then the
# suite again under sanitizers with a short fuzzing run (scripts/test-sanitized.sh).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"

# The suite writes under build*/ and temporary folders only: a file it leaves in the source tree
# (a fuzzer's artifact, a test's output) fails the run instead of waiting to be committed.
untracked_files() {
  if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
    git status --porcelain --untracked-files=all | sed -n 's/^?? //p' | sort
  fi
}
untracked_before=$(untracked_files)

MATC_CMAKE_ARGS="-DMATC_WERROR=ON ${MATC_CMAKE_ARGS:-}" bash scripts/build.sh
ctest --test-dir build --output-on-failure --parallel "$(nproc)"
# Once more under AddressSanitizer and UndefinedBehaviorSanitizer, then a minute of fuzzing
# (MATC_SKIP_SANITIZED=1 skips this locally; CI always runs it).
if [ "${MATC_SKIP_SANITIZED:-0}" != 1 ] || [ "${CI:-}" = true ]; then
  bash scripts/test-sanitized.sh
fi

untracked_after=$(untracked_files)
left_behind=$(comm -13 <(echo "$untracked_before") <(echo "$untracked_after"))
if [ -n "$left_behind" ]; then
  echo "error: the test run left files in the source tree:" >&2
  while IFS= read -r path; do printf '  %s\n' "$path" >&2; done <<<"$left_behind"
  exit 1
fi
