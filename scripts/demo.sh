#!/usr/bin/env bash
# Installs what is missing, builds in Release, and runs the demo episode: plan the head-in
# scenario, drive the plan in the Bullet simulation with closed-loop tracking, measure the
# tracking error, and film it. Outputs go to out/demo/ (override: scripts/demo.sh OUT_DIR).
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-out/demo}
scripts/install-deps.sh
scripts/build.sh build
./build/app/parksim run worlds/head_in.yaml --seed 1 --tracking closed --frames --video \
  --out "$out"
echo "demo outputs in $out: trajectory.csv plan.json executed.csv metrics.json frames/ figures/"
