#!/bin/sh
# A CI job's parksim steps (docs/ci.md): run the sweep, write JUnit, compare with the stored
# baseline and fail on a regression. The GitLab job and the GitHub workflow beside this file
# both call it.
#
#   examples/ci/parksim-ci.sh check     sweep, then compare with $BASELINE (exit 4: regression)
#   examples/ci/parksim-ci.sh refresh   sweep, then store its table as the new $BASELINE
#
# Settings (environment):
#   PARKSIM   the parksim program (default: parksim on PATH)
#   SPEC      the sweep spec (default: examples/ci/sweep.yaml)
#   BASELINE  the stored baseline table, a results.jsonl (default: ci/baseline/results.jsonl)
#   OUT       where the job writes (default: parksim-ci): sweep/ (with its page,
#             sweep/report/index.html, and each kept episode's, docs/pages.md), sweep.xml,
#             compare.xml, compare.md, compare.html
#   STRICT    1: also fail when an episode misses its tolerance (default 0: the JUnit report
#             shows those; only a regression against the baseline fails the job)
#   COMPARE_ARGS  more options for parksim compare (e.g. --confidence 0.99)
#
# Exit status: 0 no regression; 4 a regression; 2 bad input (a missing baseline, a bad spec);
# with STRICT=1, 1 when an episode missed its tolerance.
set -eu

mode=${1:-check}
PARKSIM=${PARKSIM:-parksim}
SPEC=${SPEC:-examples/ci/sweep.yaml}
BASELINE=${BASELINE:-ci/baseline/results.jsonl}
OUT=${OUT:-parksim-ci}
STRICT=${STRICT:-0}
COMPARE_ARGS=${COMPARE_ARGS:-}

case "$mode" in
  check | refresh) ;;
  *) echo "usage: $0 check|refresh" >&2; exit 2 ;;
esac

mkdir -p "$OUT"
# A fresh sweep every time (a sweep directory resumes, and a stale one would hide a change), and
# no report left from an earlier run.
rm -rf "$OUT/sweep" "$OUT/sweep.xml" "$OUT/compare.xml" "$OUT/compare.md" "$OUT/compare.html"
sweep_status=0
"$PARKSIM" sweep "$SPEC" --out "$OUT/sweep" || sweep_status=$?
# 1: some episodes missed their tolerance (listed in sweep.xml); anything else is an error.
if [ "$sweep_status" -ne 0 ] && [ "$sweep_status" -ne 1 ]; then exit "$sweep_status"; fi
# The sweep's page (sweep/report/index.html) and the JUnit report, whose cases link to it and
# to the pages of the episodes kept.
"$PARKSIM" report "$OUT/sweep" --junit "$OUT/sweep.xml" > /dev/null

if [ "$mode" = refresh ]; then
  mkdir -p "$(dirname "$BASELINE")"
  cp "$OUT/sweep/results.jsonl" "$BASELINE"
  echo "stored $OUT/sweep/results.jsonl as the baseline $BASELINE; commit it"
  exit 0
fi

compare_status=0
# shellcheck disable=SC2086 # COMPARE_ARGS is a list of options
"$PARKSIM" compare "$BASELINE" "$OUT/sweep" --markdown "$OUT/compare.md" \
  --junit "$OUT/compare.xml" --html "$OUT/compare.html" $COMPARE_ARGS || compare_status=$?
# GitHub shows this file on the run's summary page.
if [ -n "${GITHUB_STEP_SUMMARY:-}" ] && [ -f "$OUT/compare.md" ]; then
  cat "$OUT/compare.md" >> "$GITHUB_STEP_SUMMARY"
fi
if [ "$compare_status" -ne 0 ]; then exit "$compare_status"; fi
if [ "$STRICT" = 1 ] && [ "$sweep_status" -ne 0 ]; then exit "$sweep_status"; fi
exit 0
