#!/usr/bin/env bash
# libFuzzer campaigns on parksim's input readers: the world-file reader and the plan-file
# reader, built with clang (-fsanitize=fuzzer,address,undefined) into build-fuzz/. The main
# build uses g++; this is a separate, small build of just the readers.
#
#   scripts/fuzz.sh --ci                     bounded run for CI: every corpus input, then
#                                            FUZZ_RUNS (default 20000) mutations per reader
#   scripts/fuzz.sh world [libFuzzer args]   long campaign on one reader (world or plan), e.g.
#   scripts/fuzz.sh world -max_total_time=3600 -jobs=2 -workers=2
#
# Corpora live in tests/fuzz/corpus/{world,plan}/ (the crashers of issue 13 included); a long
# campaign adds what it finds to build-fuzz/corpus-<reader>/, never to the repository's corpus.
# Each input gets at most FUZZ_TIMEOUT seconds (default 10) and 2 GB: a hang or a memory blow-up
# is a failure, as is any crash or sanitizer report.
set -euo pipefail
cd "$(dirname "$0")/.."
out=build-fuzz
mkdir -p "$out"
cxx=${FUZZ_CXX:-clang++}
flags=(-std=c++20 -O1 -g -fno-omit-frame-pointer -fsanitize=fuzzer,address,undefined
       -fno-sanitize-recover=undefined -I. -isystem /usr/include/eigen3)
# The readers need the core library but not its build-provenance file (a configured header).
core=()
for f in parksim/core/*.cpp; do
  [ "$f" = parksim/core/Provenance.cpp ] || core+=("$f")
done

# Each source is compiled once into build-fuzz/obj/ (the readers share the core library's
# sources), on all cores, and again only when it or a parksim header changed since.
compile() {  # compile SOURCE into build-fuzz/obj/SOURCE.o
  local object=$out/obj/${1%.cpp}.o
  if [ ! -f "$object" ] || [ "$1" -nt "$object" ] ||
     [ -n "$(find parksim tests/fuzz -name '*.h' -newer "$object" | head -1)" ]; then
    mkdir -p "$(dirname "$object")"
    "$cxx" "${flags[@]}" -c "$1" -o "$object"
  fi
}
export -f compile
export out cxx
flags_line=$(printf '%q ' "${flags[@]}")

link() {  # link NAME OBJECTS... LIBS...
  local name=$1
  shift
  echo "== linking $out/fuzz_$name"
  "$cxx" "${flags[@]}" "$@" -o "$out/fuzz_$name"
}

# The reader's realism: section is checked by the Bullet-free parksim_realism library
# (parksim/realism/, all of it).
realism=(parksim/realism/*.cpp)
world_sources=(tests/fuzz/WorldReaderFuzz.cpp parksim/scenario/*.cpp "${realism[@]}" "${core[@]}")
plan_sources=(tests/fuzz/PlanReaderFuzz.cpp parksim/results/TrajectoryFile.cpp "${core[@]}")
echo "== compiling the readers for fuzzing (build-fuzz/obj/)"
printf '%s\n' "${world_sources[@]}" tests/fuzz/PlanReaderFuzz.cpp parksim/results/TrajectoryFile.cpp |
  FLAGS="$flags_line" xargs -P "$(nproc)" -I{} bash -c 'eval "flags=($FLAGS)"; compile "$1"' _ {}
objects() { for f in "$@"; do printf '%s\n' "$out/obj/${f%.cpp}.o"; done; }
mapfile -t world_objects < <(objects "${world_sources[@]}")
mapfile -t plan_objects < <(objects "${plan_sources[@]}")
link world "${world_objects[@]}" -lyaml-cpp
link plan "${plan_objects[@]}"

timeout_s=${FUZZ_TIMEOUT:-10}
common=(-timeout="$timeout_s" -rss_limit_mb=2048 -malloc_limit_mb=2048 -max_len=65536
        -print_final_stats=1)
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1}

if [ "${1:-}" = "--ci" ]; then
  runs=${FUZZ_RUNS:-20000}
  for reader in world plan; do
    echo "== fuzz_$reader: corpus replay, then $runs mutations (seed 1)"
    work=$(mktemp -d)
    trap 'rm -rf "$work"' EXIT
    # -runs counts mutations after the corpus; new inputs go to a scratch copy, and crash
    # reproducers into the build directory.
    cp tests/fuzz/corpus/$reader/* "$work"/
    # The outer timeout bounds the whole run even if libFuzzer's own handler hangs.
    timeout -k 10 600 "$out/fuzz_$reader" "${common[@]}" -seed=1 -runs="$runs" \
      -artifact_prefix="$out/$reader-" "$work" 2>&1 | grep -v '^    #' | tail -n 12
    rm -rf "$work"
    trap - EXIT
  done
  exit 0
fi

reader=${1:?usage: scripts/fuzz.sh --ci | scripts/fuzz.sh world|plan [libFuzzer args...]}
shift
mkdir -p "$out/corpus-$reader"
exec "$out/fuzz_$reader" "${common[@]}" -artifact_prefix="$out/$reader-" "$@" \
  "$out/corpus-$reader" "tests/fuzz/corpus/$reader"
