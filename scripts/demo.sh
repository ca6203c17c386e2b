#!/usr/bin/env bash
# Installs what is missing for the demo (scripts/install-deps.sh demo), builds in Release the
# parksim program and the libraries it links (nothing else: no tests, benchmarks or Python
# module), and runs the demo episode: plan the head-in scenario, drive the plan in the Bullet
# simulation with closed-loop tracking, measure the tracking error, and film it. Outputs go to
# out/demo/ (override: scripts/demo.sh OUT_DIR).
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-out/demo}
scripts/install-deps.sh demo
# A new build directory is configured for the program alone, so that configuring needs none of
# the test packages; scripts/test.sh and scripts/build.sh without --target turn the rest on in
# the same directory later and reuse what was compiled here.
options=()
if [ ! -f build/CMakeCache.txt ]; then
  options=(-DPARKSIM_BUILD_TESTS=OFF -DPARKSIM_BUILD_BENCH=OFF -DPARKSIM_PYTHON=OFF)
fi
# The compiler: clang unless CXX names one (scripts/build.sh says why).
scripts/build.sh build "${options[@]}" --target parksim
./build/app/parksim run worlds/head_in.yaml --seed 1 --tracking closed --frames --video \
  --out "$out"
echo "demo outputs in $out: trajectory.csv plan.json executed.csv metrics.json frames/ figures/"
