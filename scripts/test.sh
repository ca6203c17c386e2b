#!/usr/bin/env bash
# Installs what is missing (scripts/install-deps.sh build, then test while the first build
# compiles), then runs three passes:
#   1. sanitizers: every GoogleTest program and the parksim program built with clang,
#      AddressSanitizer (LeakSanitizer on, its suppressions in tests/lsan.supp) and
#      UndefinedBehaviorSanitizer, against the static libraries; all their tests;
#   2. front-ends: what the sanitizer build leaves out (the Python module, the benchmarks, the
#      documentation's example programs, the installed package and its consumer), in Release
#      against the shared libraries (build/, made PARKSIM_SHARED=ON), and their tests
#      (`ctest -L front_end`), with the test programs whose assertions are rates over many
#      seeds (`-L release`: run here once, not under the sanitizers); compiled with clang
#      unless CXX names a compiler (scripts/build.sh);
#   3. fuzzing: the readers' libFuzzer harnesses, bounded (scripts/fuzz.sh --ci).
# Passes 2 and 3 are built behind pass 1, at the lowest priority (nice 19): their compiles take
# what the sanitizer build and its tests leave of the cores (configuring, linking, tests that
# wait on a child process), and the sanitizer pass runs as fast as alone. Their output is
# printed when they are joined. Then the front-ends' tests run beside the bounded fuzzing.
# Every test runs once. Usage:
#   scripts/test.sh                              all passes
#   PARKSIM_SKIP_SANITIZERS=1 scripts/test.sh    no sanitizer build: everything in Release
#                                                against the static libraries (build/), every
#                                                test; fuzzing; then the front-end tests
#                                                against the shared libraries (build-shared/)
#   CC=gcc CXX=g++ PARKSIM_SKIP_SANITIZERS=1 scripts/test.sh
#                                                the same with GCC, in a fresh clone (CI builds
#                                                with clang only; docs/building.md)
# Timings and what each pass costs: docs/building.md.
set -euo pipefail
cd "$(dirname "$0")/.."
# What the builds compile against first; what only the tests need (a browser, Slurm, pytest,
# pandas, Jupyter, a locale) below, while the first build compiles.
scripts/install-deps.sh build
jobs=$(nproc)
# A test that hangs fails after this long instead of holding CI until its limit (tests with a
# TIMEOUT property of their own keep it). The slowest test takes about 60 s under the sanitizers.
test_timeout=${PARKSIM_TEST_TIMEOUT:-600}

# No compiler cache in CI (a clean clone, an empty cache): nothing else there uses a pass's
# objects, and a cold cache only costs (each file preprocessed once more for its key).
ccache=1
[ "${CI:-}" = true ] && ccache=0
front_ends_build() {  # front_ends_build BUILD_DIR: the front-ends (shared libraries)
  PARKSIM_CCACHE=$ccache scripts/build.sh "$1" -DPARKSIM_SHARED=ON \
    -DPARKSIM_BUILD_TESTS=ON -DPARKSIM_BUILD_BENCH=ON -DPARKSIM_PYTHON=ON \
    --target parksim_front_end_tests
}
front_ends_tests() {  # front_ends_tests BUILD_DIR LABELS: their tests (a ctest -L expression)
  ctest --test-dir "$1" --output-on-failure --parallel "$jobs" --timeout "$test_timeout" -L "$2"
}
shared_front_ends() { front_ends_build "$1" && front_ends_tests "$1" front_end; }

# Passes running behind the foreground one: each in its own process group (stopped, with its
# children, when this script exits early), its output in a log printed when it is joined.
logs=$(mktemp -d)
behind_pids=()
stop_behind() { for pid in "${behind_pids[@]}"; do kill -- "-$pid" 2>/dev/null || true; done; }
trap 'stop_behind; rm -rf "$logs"' EXIT
behind() {  # behind NAME NICENESS COMMAND...: start COMMAND in the background
  local name=$1 niceness=$2
  shift 2
  set -m
  nice -n "$niceness" "$@" < /dev/null > "$logs/$name.log" 2>&1 &
  set +m
  behind_pids+=($!)
  eval "behind_$name=$!"
}
join() {  # join NAME: wait for it, print its output; fails as it failed
  local pid_var=behind_$1 status=0
  wait "${!pid_var}" || status=$?
  echo "== (behind) $1: exit status $status"
  cat "$logs/$1.log"
  return $status
}
export -f front_ends_build
export ccache

if [ "${PARKSIM_SKIP_SANITIZERS:-0}" != 1 ]; then
  # The tests' own packages, installed while the sanitizer build compiles: on a fresh Debian 12
  # they took 72 s to fetch and install (176 MB; one core: dpkg, Python's byte-compiling), in
  # which nothing compiled (docs/building.md, "Packages behind the build"). Joined before the
  # first test.
  behind deps 0 scripts/install-deps.sh test
  # In build/, where the documentation's commands find them. The libraries compile alike
  # static and shared (cmake/TargetDefaults.cmake), so after scripts/demo.sh this pass only
  # links them again; one pass builds the libraries in Release, where a static and a shared
  # pass compiled them twice (clang's precompiled headers, which embed their build directory,
  # gave a compiler cache no hits across the two: 152 s more in CI).
  behind build 19 bash -c 'front_ends_build build && scripts/fuzz.sh --build'

  echo "== Sanitizer build (clang, ASan + LSan + UBSan) and the library's tests"
  # Only what the tests run: the GoogleTest programs and the parksim program (parksim_tests).
  # clang, -O1 -g1 (line tables: reports still name file and line): this build took 350 s on
  # 2 cores where GCC took about 840 s (docs/building.md).
  # Larger unity batches than a build for editing (docs/building.md, "CI in 10 minutes"): this
  # pass compiles everything once. Libraries in batches of 16 (not 6): 230 instead of 280 CPU s;
  # each test program's files in one batch (PARKSIM_TEST_UNITY_BATCH_SIZE=0): the four
  # programs with more than 8 files in 55 instead of 81 CPU s. Cold code at -O0: the test
  # programs but those marked OPTIMIZED, and the targets marked COLD (the command line, result
  # files, pages, reports, sweeps): PARKSIM_COLD_OPTIMIZATION, cmake/TargetDefaults.cmake.
  # Without line tables (-g0: 10 % less compile time): a sanitizer report names the functions
  # of cold code, not their lines; GoogleTest's messages keep theirs (__FILE__, __LINE__).
  # Each test program runs as 4 shards (GoogleTest's sharding, PARKSIM_TEST_SHARDS in
  # tests/CMakeLists.txt), not a process per test: a sanitized process costs about 0.1 CPU s to
  # start and check for leaks, more than most tests; the tests took 430 + 141 CPU s so, against
  # 571 + 246 one per process (docs/building.md, "Shards, lld, huge pages").
  PARKSIM_CCACHE=$ccache scripts/build.sh build-sanitize -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
    -DCMAKE_BUILD_TYPE=RelWithDebInfo -DPARKSIM_SANITIZE=ON -DPARKSIM_BUILD_BENCH=OFF \
    -DPARKSIM_PYTHON=OFF "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" \
    -DPARKSIM_UNITY_BATCH_SIZE=16 -DPARKSIM_TEST_UNITY_BATCH_SIZE=0 \
    "-DPARKSIM_COLD_OPTIMIZATION=-O0 -g0" -DPARKSIM_TEST_SHARDS=4 --target parksim_tests
  # The longest tests first, in a fresh clone too: ctest starts tests by the durations it
  # recorded (Testing/Temporary/CTestCostData.txt), and without a record in test-number order, so
  # a 20-second test could start last and run alone at the end. tests/sanitizer_costs.txt seeds
  # the record with the shards that took 3 s or more (docs/building.md says how to renew it).
  join deps
  costs=build-sanitize/Testing/Temporary/CTestCostData.txt
  if [ ! -f "$costs" ]; then
    mkdir -p "$(dirname "$costs")"
    { cat tests/sanitizer_costs.txt; echo ---; } > "$costs"
  fi
  # Leaks are checked; tests/lsan.supp names the third-party allocations that live until exit
  # by design (Mesa's OSMesa).
  # intercept_tls_get_addr=0: up to LLVM 16 and GCC 13 the runtime's __tls_get_addr interceptor
  # takes a dynamic TLS block whose address is 16 mod 4096 for one with a glibc-2.19 header and
  # reads a bogus range from before it; LeakSanitizer's tracer then dies at exit ("Tracer caught
  # signal 11", google/sanitizers#1322). Mesa's llvmpipe threads use dynamic TLS, so it hit
  # whichever render test's blocks landed there (OffscreenContextTest, FrameRecorderTest), after
  # the test had passed. Off, LeakSanitizer does not scan dynamic TLS: none of parksim's memory
  # lives there, and the render tests report no new leak without it.
  ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:intercept_tls_get_addr=0 \
  LSAN_OPTIONS="suppressions=$PWD/tests/lsan.supp:print_suppressions=0" \
  UBSAN_OPTIONS=print_stacktrace=1 \
    ctest --test-dir build-sanitize --output-on-failure --parallel "$jobs" --timeout "$test_timeout"

  echo "== Front-ends (Release, shared libraries) and the fuzzers: built behind the above"
  join build
  echo "== The front-ends' tests and the Release-only programs (rates over many seeds), beside"
  echo "   the bounded fuzzing of the readers (docs/limits.md)"
  behind fuzz 10 scripts/fuzz.sh --ci
  front_ends_tests build '^(front_end|release)'
  join fuzz
else
  scripts/install-deps.sh test
  echo "== Release build (static libraries): everything and every test"
  PARKSIM_CCACHE=$ccache scripts/build.sh build -DPARKSIM_SHARED=OFF -DPARKSIM_BUILD_TESTS=ON \
    -DPARKSIM_BUILD_BENCH=ON -DPARKSIM_PYTHON=ON
  ctest --test-dir build --output-on-failure --parallel "$jobs" --timeout "$test_timeout"
  echo "== Fuzzing the world-file and plan-file readers (bounded; docs/limits.md)"
  scripts/fuzz.sh --ci
fi

if [ "${PARKSIM_SKIP_SANITIZERS:-0}" = 1 ]; then
  echo "== The front-ends against the shared libraries"
  # With build/'s compiler (CC and CXX, or what configured build/ chose).
  if [ ! -f build-shared/CMakeCache.txt ] && [ -z "${CXX:-}" ]; then
    export CC CXX
    CC=$(sed -n "s/^CMAKE_C_COMPILER:[A-Z]*=//p" build/CMakeCache.txt)
    CXX=$(sed -n "s/^CMAKE_CXX_COMPILER:[A-Z]*=//p" build/CMakeCache.txt)
  fi
  shared_front_ends build-shared
fi
