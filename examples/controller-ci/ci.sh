#!/bin/sh
# Your controller's CI (docs/your-code.md): build the plugin against the installed parksim, run
# the sweep under `lab` realism, write JUnit, and compare with the stored baseline.
#
#   ./ci.sh check     exit 0: no regression; 4: a regression against baseline/results.jsonl
#   ./ci.sh refresh   store this run's table as the new baseline (commit it)
#
# Settings (environment): PARKSIM (default: parksim on PATH), CMAKE_PREFIX_PATH (where parksim
# is installed, if not in a standard place), SPEC (default: sweep.yaml), OUT (default: out).
set -eu
cd "$(dirname "$0")"
mode=${1:-check}
PARKSIM=${PARKSIM:-parksim}
SPEC=${SPEC:-sweep.yaml}
OUT=${OUT:-out}
case "$mode" in check | refresh) ;; *) echo "usage: $0 check|refresh" >&2; exit 2 ;; esac

cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build >/dev/null

rm -rf "$OUT"
mkdir -p "$OUT"
status=0
"$PARKSIM" sweep "$SPEC" --out "$OUT/sweep" --junit "$OUT/sweep.xml" || status=$?
# 1: some episodes missed their tolerance (the JUnit report lists them); else an error.
if [ "$status" -gt 1 ]; then exit "$status"; fi

if [ "$mode" = refresh ]; then
  mkdir -p baseline
  cp "$OUT/sweep/results.jsonl" baseline/results.jsonl
  echo "stored baseline/results.jsonl: commit it"
  exit 0
fi
# Exit 4 when a group's success rate or tracking error got significantly worse. Across the
# controller: each episode pairs with the baseline's of the same lot and noise seed whatever the
# controller's name or parameters (a retuned or renamed controller is still compared).
"$PARKSIM" compare baseline/results.jsonl "$OUT/sweep" --across controller \
  --junit "$OUT/compare.xml" --markdown "$OUT/compare.md" --html "$OUT/compare.html"
