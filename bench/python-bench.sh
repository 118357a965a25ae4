#!/usr/bin/env bash
# The Python module's speed against the C++ runtime, plain numpy and the CLI (bench/python_bench.py)
# over N generated materials (default 1000); prints the Markdown block of docs/performance.md.
#   bench/python-bench.sh [BUILD_DIR] [N]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
count=${2:-1000}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --build "$build" --target matc matc_python matc_fresnel_eval_benchmark >/dev/null

# shellcheck source=bench/generated-materials.sh
source "$root/bench/generated-materials.sh"
generate_materials "$work/materials" "$count"

"$build/bench/matc_fresnel_eval_benchmark" --benchmark_repetitions=5 \
  --benchmark_report_aggregates_only=true --benchmark_format=json >"$work/cpp.json"
median_ms() {  # benchmark name
  python3 - "$work/cpp.json" "$1" <<'PY'
import json, sys
report = json.load(open(sys.argv[1]))
print(next(b["real_time"] for b in report["benchmarks"]
           if b["aggregate_name"] == "median" and b["run_name"].startswith(sys.argv[2] + "/")))
PY
}
python=$(sed -n 's/^MATC_PYTHON_EXECUTABLE:INTERNAL=//p' "$build/CMakeCache.txt")
PYTHONPATH="$build/python" "$python" "$root/bench/python_bench.py" "$build/matc" \
  "$work/materials" "$(median_ms EvaluateFresnelEach)" "$(median_ms EvaluateFresnelSpan)"
