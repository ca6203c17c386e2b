#!/usr/bin/env bash
# Plugin overhead benchmark (issue 30, "Speed"; docs/benchmarks.md, "Plugin overhead"): parksim's
# tracking controller built in (`tracking`) against the same code registered by a plugin
# (`tracking-copy` of tests/plugin/FaultyPlugin.cpp), timed as whole commands, A and B in turn,
# PAIRS pairs after one warm-up pair, each run into a fresh output directory:
#   run      parksim run worlds/head_in.yaml, --controller tracking vs the plugin's (a plugin's
#            controller runs in a watched child process)
#   sweep    parksim sweep of worlds/sweeps/study.yaml (120 episodes), `controllers: [tracking]`
#            (worker threads) vs `plugins:` + `controllers: [tracking-copy]` (worker processes)
# and the sweep's overhead taken apart with bench_plugin_sweep, which forces the workers:
#   processes  built in on threads vs built in in processes (fork, rows as JSON through a pipe)
#   plugin     built in vs the plugin's copy, both in processes (the call into the plugin)
#
#   bench/plugin_overhead.sh BUILD_DIR [PAIRS] [WORKERS] [WORK_DIR]
#       default 5 pairs, 2 workers, /tmp/parksim-plugin-overhead
#
# BUILD_DIR must hold the targets parksim, parksim_faulty_plugin and bench_plugin_sweep. Checks
# first that the copy's rows agree with the built-in's (executed.csv bytes; every sweep row's
# non-timing values), then prints one Markdown table: B/A ratios of wall and CPU (user + sys,
# the children's included) time, median [min, max] over the pairs (/usr/bin/time counts CPU in
# 10 ms steps: coarse for `run`'s 0.08 s; use more pairs). The machine is shared: quote it with
# `uptime`'s load, printed before and after.
set -euo pipefail
cd "$(dirname "$0")/.."
[ $# -ge 1 ] || { sed -n '14,15p' "$0"; exit 2; }
build=$(realpath "$1")
pairs=${2:-5}
workers=${3:-2}
work=$(realpath -m "${4:-/tmp/parksim-plugin-overhead}")
exe=$build/app/parksim
bench=$build/bench/bench_plugin_sweep
plugin=$(find "$build" -name libparksim_faulty_plugin.so -print -quit)
for f in "$exe" "$bench" "$plugin"; do
  [ -x "$f" ] || [ -f "$f" ] || { echo "missing in $build: $f"; exit 2; }
done
rm -rf "$work"
mkdir -p "$work"

# The study spec with its worlds by absolute path and a controllers axis of one.
spec() {  # spec FILE LINE...: the study spec, then the lines
  local file=$work/$1
  shift
  sed -e "s#\.\./#$PWD/worlds/#g" worlds/sweeps/study.yaml >"$file"
  printf '%s\n' "$@" >>"$file"
}
spec builtin.yaml "controllers: [tracking]"
spec plugin.yaml "plugins: [$plugin]" "controllers: [tracking-copy]"

# timed NAME SIDE RUN COMMAND...: runs COMMAND with --out/OUT last, appends
# "NAME SIDE RUN wall user sys" to $work/times.txt. Exit codes 0 and 1 (some episode failed its
# tolerance) are results; anything else stops the benchmark.
timed() {
  local name=$1 side=$2 run=$3
  shift 3
  local out=$work/$name/$side$run rc=0
  mkdir -p "$work/$name"
  /usr/bin/time -f '%e %U %S' -o "$work/time" "$@" "$out" >"$out.stdout" 2>"$out.stderr" || rc=$?
  [ "$rc" -le 1 ] || { echo "$name $side failed ($rc): $*"; tail -3 "$out.stderr"; exit 1; }
  echo "$name $side $run $(tail -1 "$work/time")" >>"$work/times.txt"
}

# pair NAME 'A COMMAND' 'B COMMAND': run 0 is the warm-up.
pair() {
  local name=$1 a=$2 b=$3
  for run in $(seq 0 "$pairs"); do
    # shellcheck disable=SC2086  # the commands are word lists without quoting
    timed "$name" a "$run" $a
    # shellcheck disable=SC2086
    timed "$name" b "$run" $b
  done
}

echo "load before: $(uptime)"
run="$exe run worlds/head_in.yaml"
pair run "$run --controller tracking --out" \
  "$run --plugin $plugin --controller tracking-copy --out"
pair sweep "$exe sweep $work/builtin.yaml --workers $workers --out" \
  "$exe sweep $work/plugin.yaml --workers $workers --out"
pair processes "$bench $work/builtin.yaml $workers threads" \
  "$bench $work/builtin.yaml $workers processes"
pair plugin "$bench $work/builtin.yaml $workers processes" \
  "$bench $work/plugin.yaml $workers processes"
echo "load after: $(uptime)"

# Agreement: the copy's executed.csv is the built-in's, byte for byte, in every run; the sweep
# rows agree in every key that is not timing (those that differ between two built-in runs), the
# controller's name, the plugins or what depends on them (episode_id, row_checksum).
for run in $(seq 0 "$pairs"); do
  cmp "$work/run/a$run/executed.csv" "$work/run/b$run/executed.csv"
done
echo "run: executed.csv identical in all $((pairs + 1)) pairs"
/usr/bin/python3 - "$work" "$pairs" <<'PY'
import json, statistics, sys
from pathlib import Path

work, pairs = Path(sys.argv[1]), int(sys.argv[2])

def rows(d):
    return [json.loads(line) for line in (d / "results.jsonl").read_text().splitlines()]

def params(r):  # the episode, whatever its controller
    return (r["world"], r["planner"], r["seed"], r["noise_seed"])

built_in = {params(r): r for r in rows(work / "sweep/a0")}
again = {params(r): r for r in rows(work / "sweep/a1")}
timing = {k for p, r in built_in.items() for k in r if r[k] != again[p].get(k)}
ignored = timing | {"episode_id", "controller", "plugins", "row_checksum"}
compared = set()
for d in sorted((work / "sweep").glob("b*")):
    if not d.is_dir():
        continue
    copy = {params(r): r for r in rows(d)}
    assert copy.keys() == built_in.keys(), f"{d}: other episodes"
    for p, r in copy.items():
        diff = {k for k in r.keys() | built_in[p].keys() if k not in ignored
                and r.get(k) != built_in[p].get(k)}
        assert not diff, f"{d}: episode {p} differs in {sorted(diff)}"
        compared |= r.keys() - ignored
print(f"sweep: {len(built_in)} rows x {pairs + 1} runs agree in {len(compared)} keys "
      f"(max_pos_err_m, goal_pos_err_m, ...); timing keys (differ between built-in runs): "
      f"{', '.join(sorted(timing))}")

# The ratios.
t = {}
for line in (work / "times.txt").read_text().splitlines():
    name, side, run, wall, user, sys_ = line.split()
    if int(run) > 0:
        t.setdefault(name, {}).setdefault(side, []).append(
            (float(wall), float(user) + float(sys_)))
what = {
    "run": "`run` head_in: built in vs plugin (watched child process)",
    "sweep": "`sweep` study: built in (threads) vs plugin (processes)",
    "processes": "of which processes: built in, threads vs processes",
    "plugin": "of which the plugin: in processes, built in vs plugin",
}
def fmt(v):
    return f"{statistics.median(v):.3f} [{min(v):.3f}, {max(v):.3f}]"
print()
print(f"| B vs A ({pairs} pairs) | A wall (s) | B wall (s) | wall B/A | CPU B/A |")
print("|---|---:|---:|---:|---:|")
for name, label in what.items():
    a, b = t[name]["a"], t[name]["b"]
    wall = [y[0] / x[0] for x, y in zip(a, b)]
    cpu = [y[1] / x[1] for x, y in zip(a, b)]
    print(f"| {label} | {statistics.median(x[0] for x in a):.2f} | "
          f"{statistics.median(y[0] for y in b):.2f} | {fmt(wall)} | {fmt(cpu)} |")
PY
