#!/usr/bin/env bash
# The Slurm path of `parksim sweep` on a real one-node cluster (scripts/slurm-local.sh): writes
# the job-array script for a small sweep, submits it with `sbatch --wait`, merges the shards,
# and checks that the merged table equals a local `parksim sweep` of the same spec (timing
# columns aside). Needs root and slurm-wlm + munge; exits 77 (skipped) without them.
# Usage: slurm_test.sh PARKSIM_EXE WORK_DIR
set -euo pipefail
exe=$(realpath "$1")
work=$(realpath -m "$2")
src=$(cd "$(dirname "$0")/../.." && pwd)

if [ "$(id -u)" -ne 0 ]; then echo "skipped: the one-node Slurm cluster needs root"; exit 77; fi
for p in sbatch slurmctld slurmd munged python3; do
  command -v "$p" >/dev/null || { echo "skipped: $p not installed (scripts/install-deps.sh)"; exit 77; }
done

rm -rf "$work"
mkdir -p "$work"
cluster=$work/cluster
trap '"$src/scripts/slurm-local.sh" stop "$cluster"' EXIT
timeout 60 "$src/scripts/slurm-local.sh" start "$cluster"
export SLURM_CONF=$cluster/slurm.conf

cat > "$work/spec.yaml" <<SPEC
format: parksim-sweep/1
name: slurm-test
worlds: [$src/worlds/head_in.yaml]
planners: [rrt-goal-connect]
seeds: {from: 1, to: 6}
SPEC

"$exe" sweep "$work/spec.yaml" --out "$work/on-slurm" --slurm --slurm-shards 3 \
  --slurm-mem 200M --slurm-time 00:05:00
timeout 90 sbatch --wait "$work/on-slurm/sweep.sbatch"
"$exe" merge "$work/on-slurm"

rc=0
"$exe" sweep "$work/spec.yaml" --out "$work/local" --workers 2 || rc=$?
[ "$rc" -le 1 ] || { echo "local sweep failed ($rc)"; exit 1; }

python3 - "$work/on-slurm/results.jsonl" "$work/local/results.jsonl" <<'PY'
import json, sys
# row_checksum seals the timing columns too, so it differs with them.
TIMING = {"plan_time_s", "plan_first_solution_s", "sim_wall_s", "episode_wall_s",
          "plan_cost_history", "plan_phase_times_s", "row_checksum"}
def table(path):
    rows = [json.loads(line) for line in open(path)]
    return {r["episode_id"]: {k: v for k, v in r.items() if k not in TIMING} for r in rows}, len(rows)
slurm, n_slurm = table(sys.argv[1])
local, n_local = table(sys.argv[2])
assert n_slurm == len(slurm) == 6, f"Slurm table: {n_slurm} rows, {len(slurm)} ids, expected 6"
assert n_local == len(local) == 6, f"local table: {n_local} rows, {len(local)} ids"
for i in sorted(local):
    assert i in slurm, f"episode {i} missing from the Slurm table"
    assert slurm[i] == local[i], f"episode {i} differs:\n{slurm[i]}\n{local[i]}"
print("slurm_test: merged Slurm table == local table (6 episodes, timing columns aside)")
PY
