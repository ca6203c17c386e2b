#!/usr/bin/env bash
# Sweep scale benchmark (issue 22; docs/sweeps.md, "Scale"): a sweep of N short episodes
# (default 100,000) of bench/scale/tiny.yaml through the real pipeline (Hybrid A*, open loop),
# then resume, merge, report and verify of the whole table, each timed with /usr/bin/time -v.
# While the sweep runs, its resident memory and CPU time are sampled against the rows written
# (bench/scale/sample.py), and fitted after the first 1,000 rows: memory growth per row (bytes)
# and CPU time per row in each tenth of the run (constant time per row: last tenth / second).
#
#   bench/sweep_scale.sh [EPISODES] [WORK_DIR] [WORKERS]
#       default 100000 episodes in /tmp/parksim-scale, 2 workers; PARKSIM=path/to/parksim
#
# Prints a Markdown table. The machine is shared: quote it with `uptime`'s load.
set -euo pipefail
cd "$(dirname "$0")/.."
episodes=${1:-100000}
work=$(realpath -m "${2:-/tmp/parksim-scale}")
workers=${3:-2}
exe=$(realpath "${PARKSIM:-build/app/parksim}")
rm -rf "$work"
mkdir -p "$work"
cat > "$work/spec.yaml" <<SPEC
format: parksim-sweep/1
name: scale
worlds: [$PWD/bench/scale/tiny.yaml]
planners: hybrid-a-star
tracking: open
seeds: {from: 1, to: $episodes}
SPEC
echo "load before: $(uptime)"

timed() {  # timed NAME COMMAND...: /usr/bin/time -v into $work/NAME.time
  local name=$1
  shift
  local rc=0
  /usr/bin/time -v -o "$work/$name.time" "$@" >"$work/$name.out" 2>"$work/$name.err" || rc=$?
  [ "$rc" -le 1 ] || { echo "$name failed ($rc):"; tail -5 "$work/$name.err"; exit 1; }
}
field() {  # field NAME "Label": a value from /usr/bin/time -v's output
  grep -F "$2" "$work/$1.time" | head -1 | awk -F': ' '{print $2}'
}

# The sweep, sampled (RSS, CPU time, rows) every 0.5 s.
"$exe" sweep "$work/spec.yaml" --out "$work/table" --workers "$workers" \
  >"$work/sweep.out" 2>"$work/sweep.err" &
sweep_pid=$!
/usr/bin/python3 bench/scale/sample.py "$sweep_pid" "$work/table/results.jsonl" \
  "$work/samples.csv"
wait "$sweep_pid" || [ $? -le 1 ] || { echo "sweep failed"; tail -5 "$work/sweep.err"; exit 1; }

timed resume "$exe" sweep "$work/spec.yaml" --out "$work/table" --workers "$workers"
timed merge "$exe" merge "$work/table" --out "$work/merged"
timed report "$exe" report "$work/table" --out "$work/report"
timed verify "$exe" verify "$work/table"
rows=$(wc -l < "$work/table/results.jsonl")
echo "load after: $(uptime)"

/usr/bin/python3 bench/scale/sample.py --fit "$work/samples.csv"
echo
echo "| command ($rows rows) | wall (s) | CPU (s) | max RSS (MB) |"
echo "|---|---:|---:|---:|"
for step in resume merge report verify; do
  wall=$(field "$step" "Elapsed (wall clock)")
  user=$(field "$step" "User time")
  sys=$(field "$step" "System time")
  rss=$(field "$step" "Maximum resident set size")
  printf '| %s | %s | %.1f | %.0f |\n' "$step" "$wall" "$(echo "$user + $sys" | bc)" \
    "$(echo "$rss / 1024" | bc)"
done
echo
echo "table: $(du -h "$work/table/results.jsonl" | cut -f1) results.jsonl, $(du -h "$work/table/results.csv" | cut -f1) results.csv"
