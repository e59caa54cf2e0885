#!/usr/bin/env bash
# Browser test of the HTML report: msmesh writes a report of the built-in example, headless
# Chromium (through chromedriver) loads it from a file:// URL and check_report.py checks that
# the 3D viewer renders without console errors and that a screenshot shows the mesh.
#
# Usage: tests/browser/run_browser_test.sh MSMESH_BINARY [WORK_DIR]
# Exit 0 pass, 1 fail, 77 skipped (Chromium, chromedriver or python3 missing: Debian packages
# chromium and chromium-driver). Set MSMESH_REQUIRE_BROWSER=1 to fail instead of skipping.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
msmesh=${1:?usage: run_browser_test.sh MSMESH_BINARY [WORK_DIR]}
msmesh=$(cd "$(dirname "$msmesh")" && pwd)/$(basename "$msmesh")
work=${2:-$(mktemp -d)}

skip() {
  if [ "${MSMESH_REQUIRE_BROWSER:-0}" = 1 ]; then
    echo "FAIL: $1 (MSMESH_REQUIRE_BROWSER=1)"
    exit 1
  fi
  echo "SKIP: $1 - the browser test of the HTML report needs it (Debian: apt-get install chromium chromium-driver)"
  exit 77
}
command -v "${CHROMIUM:-chromium}" >/dev/null 2>&1 || skip "chromium is not installed"
command -v "${CHROMEDRIVER:-chromedriver}" >/dev/null 2>&1 || skip "chromedriver is not installed"
command -v python3 >/dev/null 2>&1 || skip "python3 is not installed"

mkdir -p "$work"
cd "$work"
"$msmesh" shape fandisk --resolution 10 -o clean.obj >/dev/null
"$msmesh" noise clean.obj -o noisy.obj --sigma 0.3 --seed 7 >/dev/null
"$msmesh" denoise noisy.obj -o denoised.obj --truth clean.obj --report report.html -q >/dev/null
"$msmesh" segment clean.obj -o segments.ply --report segments.html -q >/dev/null
"$msmesh" holes clean.obj -o holes.obj --count 2 --on-features --seed 2 >/dev/null
"$msmesh" inpaint holes.obj -o filled.obj --truth clean.obj --report inpaint.html -q >/dev/null
for r in report segments inpaint; do
  echo "== $r.html ($(wc -c < $r.html) bytes)"
  mkdir -p "$work/$r"
  python3 "$here/check_report.py" "$r.html" "$work/$r"
done
