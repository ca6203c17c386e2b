#!/usr/bin/env bash
# Parameter studies at scale (docs/sweeps.md, "Parameter studies at scale"): times, as whole
# processes with /usr/bin/time, side by side with their baselines, alternating runs:
#   1. reading and expanding a 10,000-episode sampled spec of the study lot (three parameters
#      drawn per sample; every sample's world read again and checked): `parksim sweep
#      bench/parameter_study/study_10k.yaml --list`, against the same count of plain episodes
#      (plain_10k.yaml: 10,000 planner seeds);
#   2. `parksim report` of a 10,000-row table of that shape (tiny_10k.yaml: the same three
#      parameters on the cheapest whole episode, so that the table takes a minute to make, not
#      hours; the report's work depends on the rows and parameters, not the lot), against the
#      report of 10,000 plain rows (tiny_plain_10k.yaml): the per-parameter tables and plots
#      are the difference.
# Usage: bench/parameter_study.sh [WORK_DIR] [RUNS]   (default /tmp/parksim-parameter-study, 5)
set -euo pipefail
cd "$(dirname "$0")/.."
work=${1:-/tmp/parksim-parameter-study}
runs=${2:-5}
exe=${PARKSIM_EXE:-build/app/parksim}
mkdir -p "$work"
echo "load average at the start: $(cut -d' ' -f1-3 /proc/loadavg)"

# "wall user sys maxrss_kb" of one run of the command.
timed() {
  /usr/bin/time -f "%e %U %S %M" -o "$work/time.txt" "$@" >/dev/null 2>&1 || true
  tail -n 1 "$work/time.txt"  # after "Command exited with non-zero status N", if any
}

# Runs A and B alternately RUNS times; prints the medians of each and of A/B's wall, pair by pair.
pair() {
  local name=$1 a=$2 b=$3
  : >"$work/a.txt"
  : >"$work/b.txt"
  for _ in $(seq "$runs"); do
    timed $a >>"$work/a.txt"
    timed $b >>"$work/b.txt"
  done
  python3 - "$name" "$work/a.txt" "$work/b.txt" <<'PY'
import statistics, sys
name, a, b = sys.argv[1], [l.split() for l in open(sys.argv[2])], [l.split() for l in open(sys.argv[3])]
med = lambda rows, i: statistics.median(float(r[i]) for r in rows)
ratio = statistics.median(float(x[0]) / float(y[0]) for x, y in zip(a, b))
print(f"| {name} | {med(a, 0):.2f} | {med(a, 1) + med(a, 2):.2f} | {med(a, 3) / 1024:.0f} "
      f"| {med(b, 0):.2f} | {med(b, 1) + med(b, 2):.2f} | {med(b, 3) / 1024:.0f} | {ratio:.2f} |")
PY
}

for spec in tiny_10k tiny_plain_10k; do
  # Resumes: a second call runs nothing.
  "$exe" sweep "bench/parameter_study/$spec.yaml" --out "$work/$spec" >/dev/null 2>&1 || true
done
echo "| command | wall (s) | CPU (s) | max RSS (MB) | baseline wall (s) | CPU (s) | max RSS (MB) | wall / baseline |"
echo "|---|---:|---:|---:|---:|---:|---:|---:|"
pair "sweep study_10k.yaml --list (read + expand)" \
  "$exe sweep bench/parameter_study/study_10k.yaml --list" \
  "$exe sweep bench/parameter_study/plain_10k.yaml --list"
pair "report of 10,000 rows, 3 parameters" \
  "$exe report $work/tiny_10k --out $work/tiny_10k.report" \
  "$exe report $work/tiny_plain_10k --out $work/tiny_plain_10k.report"
