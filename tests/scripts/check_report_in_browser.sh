#!/usr/bin/env bash
# matc report, opened in headless Chromium: every plot on the page must decode (the page's script
# counts them into <body data-plots-loaded>), and a screenshot must show the curves in their
# colours (ours, Schlick, F82-tint, exact).
#   check_report_in_browser.sh MATC PNG_COLOUR_COUNT MATERIALS_DIR
set -euo pipefail
matc=$1
colour_count=$2
materials=$3
chromium=$(command -v chromium || command -v chromium-browser || true)
[[ -n $chromium ]] || { echo "chromium not found (scripts/install-deps.sh installs Debian's chromium)"; exit 1; }

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$matc" report -o "$work/report" "$materials"/*.json
expected=$(ls "$materials"/*.json | wc -l)

# Root in CI: Chromium's sandbox needs a user namespace it does not get there; containers often
# have a small /dev/shm.
browser=("$chromium" --headless --no-sandbox --disable-gpu --disable-dev-shm-usage
         --user-data-dir="$work/profile" --virtual-time-budget=5000)
dom=$("${browser[@]}" --dump-dom "file://$work/report/index.html" 2>/dev/null)
loaded=$(grep -o 'data-plots-loaded="[0-9]*"' <<<"$dom" | grep -o '[0-9]*' || true)
echo "plots decoded by the browser: ${loaded:-none} of $expected"
[[ "$loaded" == "$expected" ]] || { echo "FAIL: the page did not show every plot"; exit 1; }

# The first plot sits below the summary table; a tall window holds both.
"${browser[@]}" --window-size=1100,1600 --screenshot="$work/page.png" \
  "file://$work/report/index.html" >/dev/null 2>&1
[[ -s $work/page.png ]] || { echo "FAIL: no screenshot"; exit 1; }
status=0
for entry in "ours #d95f02 400" "Schlick #1b9e77 200" "F82-tint #7570b3 100" "exact #000000 400"; do
  read -r name colour minimum <<<"$entry"
  pixels=$("$colour_count" "$work/page.png" "$colour")
  echo "$name ($colour): $pixels pixels (need $minimum)"
  (( pixels >= minimum )) || status=1
done
[[ $status == 0 ]] || { echo "FAIL: the screenshot does not show the plotted curves"; exit 1; }
echo "report renders in $("$chromium" --version 2>/dev/null | head -1)"
