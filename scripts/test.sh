#!/usr/bin/env bash
# Installs what is missing, builds in Release and runs the whole test suite with ctest, then
# runs the readers' libFuzzer harnesses for a bounded number of inputs (scripts/fuzz.sh --ci),
# then builds the tests again with AddressSanitizer + UndefinedBehaviorSanitizer and runs them.
# Usage: scripts/test.sh            (both passes)
#        PARKSIM_SKIP_SANITIZERS=1 scripts/test.sh   (Release pass only)
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh

echo "== Release build and tests"
scripts/build.sh build
ctest --test-dir build --output-on-failure --parallel "$(nproc)"

echo "== Fuzzing the world-file and plan-file readers (bounded; docs/limits.md)"
scripts/fuzz.sh --ci

if [ "${PARKSIM_SKIP_SANITIZERS:-0}" != 1 ]; then
  echo "== ASan + UBSan build and tests"
  # -O1 -g1 (line tables: reports still name file and line) compiles about 35 % faster than
  # -O2 -g under the sanitizers (measured on Episode.cpp and EpisodeTest.cpp: 14.7 -> 9.2 s and
  # 22.4 -> 13.9 s), which keeps CI within its time on 2 cores.
  scripts/build.sh build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DPARKSIM_SANITIZE=ON \
    -DPARKSIM_BUILD_BENCH=OFF "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG"
  # llvmpipe keeps driver allocations alive until exit; leak checking is for our code paths,
  # which the Release valgrind-free run above already exercises.
  ASAN_OPTIONS=detect_leaks=0:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1 \
    ctest --test-dir build-asan --output-on-failure --parallel "$(nproc)"
fi
