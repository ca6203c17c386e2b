#!/usr/bin/env bash
# Configures and builds parksim.
#   scripts/build.sh [BUILD_DIR] [cmake arguments...] [--target TARGET...]
# BUILD_DIR defaults to build. The cmake arguments apply when the directory is configured (and
# again on a later call that passes them); --target builds only those targets and what they need.
# Without --target it builds everything: the tests, the benchmarks and the Python module are
# turned on (unless the arguments name PARKSIM_BUILD_TESTS, PARKSIM_BUILD_BENCH or
# PARKSIM_PYTHON), so a directory scripts/demo.sh configured for the program alone gets them
# too, and what they need is installed first (scripts/install-deps.sh test). Examples:
#   scripts/build.sh build                                      everything (Release)
#   scripts/build.sh build --target parksim                     the command line and its libraries
#   scripts/build.sh build-sanitize -DPARKSIM_SANITIZE=ON --target parksim_tests
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${1:-build}
shift || true
cmake_args=()
targets=()
while [ $# -gt 0 ]; do
  if [ "$1" = --target ]; then
    shift
    targets=("$@")
    break
  fi
  cmake_args+=("$1")
  shift
done

# Everything: the parts a directory may have been configured without (scripts/demo.sh turns
# them off to configure without the test packages) are turned on again.
if [ ${#targets[@]} -eq 0 ]; then
  for option in PARKSIM_BUILD_TESTS PARKSIM_BUILD_BENCH PARKSIM_PYTHON; do
    [[ " ${cmake_args[*]} " == *" -D$option="* ]] || cmake_args+=("-D$option=ON")
  done
  # Their packages (GoogleTest, Google Benchmark, pybind11, NumPy, ...): installed when missing
  # (as root), or named in one line. Only on Debian, whose packages the script knows.
  if command -v dpkg-query >/dev/null; then scripts/install-deps.sh test; fi
fi

generator=()
command -v ninja >/dev/null && generator=(-G Ninja)
# A compiler cache where one is installed (not required; PARKSIM_CCACHE=0 turns it off): repeated
# builds of the same sources on one machine then cost seconds instead of minutes. Its settings
# go into the launcher, so that `cmake --build` without this script gets them too: paths relative
# to the source tree (clones share entries) and the sloppiness precompiled headers need.
launcher=()
if [ "${PARKSIM_CCACHE:-1}" != 0 ] && command -v ccache >/dev/null; then
  ccache_launcher="/usr/bin/env;CCACHE_BASEDIR=$PWD;CCACHE_SLOPPINESS=pch_defines,time_macros,include_file_mtime,include_file_ctime;ccache"
  launcher=("-DCMAKE_C_COMPILER_LAUNCHER=$ccache_launcher" "-DCMAKE_CXX_COMPILER_LAUNCHER=$ccache_launcher")
fi
# clang when a new directory is configured and no compiler is named (CXX, or
# -DCMAKE_CXX_COMPILER=...): it builds parksim in about half of GCC's time (the demo's program
# 97 s against 190 s on 2 cores, docs/building.md) and the outputs are the same bytes.
# CXX=g++ CC=gcc builds with GCC, which is supported too.
compiler=()
if [ -z "${CXX:-}" ] && command -v clang++ >/dev/null &&
   [[ " ${cmake_args[*]} " != *" -DCMAKE_CXX_COMPILER="* ]]; then
  compiler=(-DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++)
fi
if [ ! -f "$build_dir/CMakeCache.txt" ]; then
  cmake -S . -B "$build_dir" "${generator[@]}" "${launcher[@]}" -DCMAKE_BUILD_TYPE=Release \
    "${compiler[@]}" "${cmake_args[@]}"
elif [ ${#cmake_args[@]} -gt 0 ]; then
  cmake -S . -B "$build_dir" "${cmake_args[@]}" >/dev/null
fi
# The compilers' memory on transparent huge pages, where the kernel gives them on request
# (madvise mode, as on Debian): a cold build's compiles take 8-14 % less CPU time, fewer page
# faults and TLB misses (docs/building.md, "Shards, lld, huge pages"). Harmless elsewhere.
export GLIBC_TUNABLES=${GLIBC_TUNABLES:+$GLIBC_TUNABLES:}glibc.malloc.hugetlb=1
build=(cmake --build "$build_dir" --parallel "$(nproc)")
[ ${#targets[@]} -gt 0 ] && build+=(--target "${targets[@]}")
"${build[@]}"
