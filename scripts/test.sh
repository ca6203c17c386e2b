#!/usr/bin/env bash
# Installs what is missing (scripts/install-deps.sh test), then runs four passes:
#   1. sanitizers: every GoogleTest program and the parksim program built with clang,
#      AddressSanitizer (LeakSanitizer on, its suppressions in tests/lsan.supp) and
#      UndefinedBehaviorSanitizer; all their tests;
#   2. Release: the front-ends the sanitizer build leaves out (the Python module, the
#      benchmarks, the documentation's example programs, the installed package) and their
#      tests (`ctest -L front_end`), compiled with clang unless CXX names a compiler
#      (scripts/build.sh);
#   3. fuzzing: the readers' libFuzzer harnesses, bounded (scripts/fuzz.sh --ci);
#   4. shared libraries (PARKSIM_SHARED=ON): the parksim program and the Python module, the
#      installed-package consumer and the Python tests against them.
# Every test runs once. Usage:
#   scripts/test.sh                              all passes
#   PARKSIM_SKIP_SANITIZERS=1 scripts/test.sh    no sanitizer build: pass 2 builds and runs
#                                                every test in Release instead
#   CC=gcc CXX=g++ PARKSIM_SKIP_SANITIZERS=1 scripts/test.sh
#                                                the same with GCC, in a fresh clone (CI builds
#                                                with clang only; docs/building.md)
# Timings and what each pass costs: docs/building.md.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh test
jobs=$(nproc)

# In CI (a clean clone) the compiler cache starts empty and lives in this clone only: it lets
# pass 4 take the objects pass 2 compiled (same flags) instead of compiling them again.
if [ "${CI:-}" = true ] && [ -z "${CCACHE_DIR:-}" ]; then
  export CCACHE_DIR=$PWD/build-ccache
fi

if [ "${PARKSIM_SKIP_SANITIZERS:-0}" != 1 ]; then
  echo "== Sanitizer build (clang, ASan + LSan + UBSan) and the library's tests"
  # Only what the tests run: the GoogleTest programs and the parksim program (parksim_tests).
  # clang, -O1 -g1 (line tables: reports still name file and line): this build took 350 s on
  # 2 cores where GCC took about 840 s (docs/building.md).
  # No compiler cache in CI: nothing else uses these objects, and a cold cache only costs (each
  # file preprocessed once more for its key).
  ccache=1
  [ "${CI:-}" = true ] && ccache=0
  PARKSIM_CCACHE=$ccache scripts/build.sh build-sanitize -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
    -DCMAKE_BUILD_TYPE=RelWithDebInfo -DPARKSIM_SANITIZE=ON -DPARKSIM_BUILD_BENCH=OFF \
    -DPARKSIM_PYTHON=OFF "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" \
    --target parksim_tests
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
    ctest --test-dir build-sanitize --output-on-failure --parallel "$jobs"
  release_targets=(--target parksim_front_end_tests)
  release_tests=(-L front_end)
else
  release_targets=()
  release_tests=()
fi

echo "== Release build: the front-ends and their tests"
scripts/build.sh build -DPARKSIM_BUILD_TESTS=ON -DPARKSIM_BUILD_BENCH=ON -DPARKSIM_PYTHON=ON \
  "${release_targets[@]}"
ctest --test-dir build --output-on-failure --parallel "$jobs" "${release_tests[@]}"

echo "== Fuzzing the world-file and plan-file readers (bounded; docs/limits.md)"
scripts/fuzz.sh --ci

echo "== Shared libraries: the installed package and the Python module"
# With the Release pass's compiler (whatever configured build/ chose), so that
# the compiler cache serves pass 2's objects.
shared_options=()
if [ ! -f build-shared/CMakeCache.txt ]; then
  for lang in C CXX; do
    compiler=$(sed -n "s/^CMAKE_${lang}_COMPILER:[A-Z]*=//p" build/CMakeCache.txt)
    shared_options+=("-DCMAKE_${lang}_COMPILER=$compiler")
  done
fi
scripts/build.sh build-shared -DPARKSIM_SHARED=ON -DPARKSIM_BUILD_BENCH=OFF \
  "${shared_options[@]}" --target parksim parksim_python
ctest --test-dir build-shared --output-on-failure --parallel "$jobs" \
  -R '^(package\.consumer|python\.test_plan_run|python\.test_world)$'
