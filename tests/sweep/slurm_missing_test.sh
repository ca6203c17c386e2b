#!/usr/bin/env bash
# A Slurm array task killed in the middle of its shard (SIGKILL to everything it runs, as a node
# failure would), on a real one-node cluster (scripts/slurm-local.sh), then one command finds
# and resubmits only the incomplete work: `parksim sweep SPEC --out DIR --slurm --missing
# --wait` must submit array task 1 alone, leave the complete shards' tables untouched, and the
# merged table must equal a local sweep of the same spec (timing columns aside). Waits are
# bounded (a hang fails); nothing is timed. Needs root and slurm-wlm + munge; exits 77
# (skipped) without them.
# Usage: slurm_missing_test.sh PARKSIM_EXE WORK_DIR
set -euo pipefail
exe=$(realpath "$1")
work=$(realpath -m "$2")
src=$(cd "$(dirname "$0")/../.." && pwd)

if [ "$(id -u)" -ne 0 ]; then echo "skipped: the one-node Slurm cluster needs root"; exit 77; fi
for p in sbatch squeue scancel slurmctld slurmd munged python3 pkill; do
  command -v "$p" >/dev/null || { echo "skipped: $p not installed (scripts/install-deps.sh)"; exit 77; }
done

rm -rf "$work"
mkdir -p "$work"
cluster=$work/cluster
trap '"$src/scripts/slurm-local.sh" stop "$cluster"' EXIT
timeout 60 "$src/scripts/slurm-local.sh" start "$cluster"
export SLURM_CONF=$cluster/slurm.conf

# 24 closed-loop episodes of the study's head-in world, 8 per shard: each takes long enough
# (a planned and simulated episode) that shard 1 is caught after its first row.
cat > "$work/spec.yaml" <<SPEC
format: parksim-sweep/1
name: slurm-missing
worlds: [$src/worlds/head_in.yaml]
planners: [rrt-goal-connect]
seeds: {from: 1, to: 24}
SPEC
dir=$work/on-slurm
"$exe" sweep "$work/spec.yaml" --out "$dir" --slurm --slurm-shards 3 --slurm-mem 200M \
  --slurm-time 00:10:00
job=$(sbatch --parsable "$dir/sweep.sbatch")
job=${job%%;*}
echo "submitted job $job"

rows() { [ -f "$1" ] && wc -l < "$1" || echo 0; }
# Shard 1's first row, then SIGKILL to its task (every process of it, the batch shell too).
# The task's parksim is stopped (SIGSTOP, from here: this is its node) the moment the row is
# seen: a Release build ran the shard's other 7 episodes in about 0.2 s, and the kill through
# slurmctld and slurmd came after all 8 rows in 1 run of 5.
for _ in $(seq 12000); do
  [ "$(rows "$dir/shards/1/results.jsonl")" -ge 1 ] && break
  sleep 0.01
done
pkill -STOP -f -- "--shard 1/3 " || true
[ "$(rows "$dir/shards/1/results.jsonl")" -ge 1 ] || { echo "shard 1 wrote no row in 120 s"; exit 1; }
scancel --full --signal=KILL "${job}_1"
# All of the job's tasks gone from the queue (the killed one, and the others finishing).
for _ in $(seq 1800); do
  [ -z "$(squeue -h -j "$job" 2>/dev/null)" ] && break
  sleep 0.1
done
[ -z "$(squeue -h -j "$job" 2>/dev/null)" ] || { echo "job $job still queued after 180 s"; exit 1; }
killed_rows=$(rows "$dir/shards/1/results.jsonl")
echo "shard 1 killed with $killed_rows of 8 rows"
[ "$killed_rows" -lt 8 ] || { echo "shard 1 finished before the kill: nothing to test"; exit 1; }

# merge sees the hole.
rc=0
"$exe" merge "$dir" || rc=$?
[ "$rc" -eq 1 ] || { echo "merge of the incomplete sweep: exit $rc, expected 1"; exit 1; }

# One command: only task 1 is resubmitted; the complete shards are not touched.
sum_others() { cat "$dir/shards/0/results.jsonl" "$dir/shards/2/results.jsonl" | md5sum; }
before=$(sum_others)
"$exe" sweep "$work/spec.yaml" --out "$dir" --slurm --missing --wait >"$work/missing.out"
cat "$work/missing.out"
# The resubmitted task asked for what the first submission asked, not the defaults.
grep -qx '#SBATCH --mem=200M' "$dir/sweep.sbatch" &&
  grep -qx '#SBATCH --time=00:10:00' "$dir/sweep.sbatch" ||
  { echo "--missing did not ask for the first submission's memory and time:"; cat "$dir/sweep.sbatch"; exit 1; }
grep -q "array tasks 1 of 3 (" "$work/missing.out" ||
  { echo "--missing did not submit exactly task 1"; exit 1; }
[ "$(sum_others)" = "$before" ] || { echo "a complete shard's table changed"; exit 1; }
[ "$(rows "$dir/shards/1/results.jsonl")" -eq 8 ] || { echo "shard 1 still incomplete"; exit 1; }
"$exe" sweep "$work/spec.yaml" --out "$dir" --slurm --missing | grep -q "every shard is complete"
"$exe" merge "$dir"
"$exe" verify "$dir"

rc=0
"$exe" sweep "$work/spec.yaml" --out "$work/local" --workers 2 || rc=$?
[ "$rc" -le 1 ] || { echo "local sweep failed ($rc)"; exit 1; }

python3 - "$dir/results.jsonl" "$work/local/results.jsonl" <<'PY'
import json, sys
TIMING = {"plan_time_s", "plan_first_solution_s", "sim_wall_s", "episode_wall_s",
          "plan_cost_history", "plan_phase_times_s", "row_checksum"}
def table(path):
    rows = [json.loads(line) for line in open(path)]
    return {r["episode_id"]: {k: v for k, v in r.items() if k not in TIMING} for r in rows}, len(rows)
slurm, n_slurm = table(sys.argv[1])
local, n_local = table(sys.argv[2])
assert n_slurm == len(slurm) == 24, f"Slurm table: {n_slurm} rows, {len(slurm)} ids, expected 24"
assert n_local == len(local) == 24, f"local table: {n_local} rows"
for i in sorted(local):
    assert i in slurm, f"episode {i} missing from the merged table"
    assert slurm[i] == local[i], f"episode {i} differs:\n{slurm[i]}\n{local[i]}"
print("slurm_missing_test: killed task 1 resubmitted alone; merged table == local table "
      "(24 episodes, timing columns aside)")
PY
