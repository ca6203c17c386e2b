#!/usr/bin/env bash
# libFuzzer campaigns on parksim's input readers, built with clang
# (-fsanitize=fuzzer,address,undefined) into build-fuzz/, apart from the CMake builds: this is a
# separate, small build of just the readers:
#   world    the world-file reader                  plan      the plan-file reader
#   spec     the sweep-spec reader                  jsonl     results.jsonl (sweep, merge, report)
#   csv      results.csv (verify, a resumed sweep)  manifest  sweep.json
#   dict     Python's dict-to-world path, C++ half (JSON as json.dumps writes it -> world)
#
#   scripts/fuzz.sh --ci                     bounded run for CI: every corpus input, then
#                                            FUZZ_RUNS (default 20000) mutations per reader,
#                                            FUZZ_TABLE_RUNS (2000) for the jsonl and csv tables;
#                                            then the dict path's Python half
#                                            (tests/fuzz/world_dict_fuzz.py, FUZZ_DICT_RUNS,
#                                            default 2000) when build/python has the module
#   scripts/fuzz.sh world [libFuzzer args]   long campaign on one reader, e.g.
#   scripts/fuzz.sh world -max_total_time=3600 -jobs=2 -workers=2
#
# Corpora live in tests/fuzz/corpus/<reader>/ (the crashers found so far included); a long
# campaign adds what it finds to build-fuzz/corpus-<reader>/, never to the repository's corpus.
# Each input gets at most FUZZ_TIMEOUT seconds (default 10) and 2 GB: a hang or a memory blow-up
# is a failure, as is any crash or sanitizer report.
set -euo pipefail
cd "$(dirname "$0")/.."
out=build-fuzz
mkdir -p "$out"
cxx=${FUZZ_CXX:-clang++}
# -ffunction-sections with --gc-sections at the link drop what no harness uses.
# -g1: line tables, enough for the reports' stack traces, and faster to compile than -g.
flags=(-std=c++20 -O1 -g1 -fno-omit-frame-pointer -fsanitize=fuzzer,address,undefined
       -fno-sanitize-recover=undefined -ffunction-sections -fdata-sections -I.
       -isystem /usr/include/eigen3 -isystem /usr/include/ompl-1.5 -isystem /usr/include/bullet
       -isystem /usr/include/libxml2)
# Sources are found by name, and folders by their whole tree: files move between folders and
# subfolders (docs/architecture.md), and a source's name is unique under parksim/.
src() {  # src NAME.cpp...: the path of each (one line each); fails when one is not found
  local name path
  for name in "$@"; do
    path=$(find parksim -name "$name" -print -quit)
    [ -n "$path" ] || { echo "fuzz.sh: no $name under parksim/" >&2; return 1; }
    echo "$path"
  done
}
sources_under() {  # sources_under DIR: every source under DIR, subfolders included, sorted
  find "$1" -name '*.cpp' | LC_ALL=C sort
}
# The readers need the core library but not its build-provenance file (a configured header).
mapfile -t core < <(sources_under parksim/core | grep -v '/Provenance\.cpp$')

# Each source is compiled once into build-fuzz/obj/ (the readers share the core library's
# sources), on all cores, and again only when it or a parksim header changed since.
# The sweep-spec reader takes its name lists (planners, steerings, timings) from
# parksim/planner/base/PlanScenario.cpp, whose other functions need the whole planner (OMPL, Bullet),
# its record format's names from parksim/results/episode/ExecutedFile.cpp (the record writers), and
# its files policy's from parksim/pipeline/EpisodeRequest.cpp.
# The fuzzer's coverage tables keep every instrumented function alive, so that file is compiled
# without them (still with ASan and UBSan, as .nocov.o) and --gc-sections drops what the spec
# reader does not call.
nocov="$(src PlanScenario.cpp ExecutedFile.cpp | tr '\n' ' ')"
object_of() {  # the object of SOURCE
  case " $nocov " in *" $1 "*) echo "$out/obj/${1%.cpp}.nocov.o" ;; *) echo "$out/obj/${1%.cpp}.o" ;; esac
}
compile() {  # compile SOURCE into build-fuzz/obj/SOURCE.o
  local object
  object=$(object_of "$1")
  local f=("${flags[@]}")
  case "$object" in *.nocov.o) f=("${f[@]/-fsanitize=fuzzer,address,undefined/-fsanitize=address,undefined}") ;; esac
  if [ ! -f "$object" ] || [ "$1" -nt "$object" ] ||
     [ -n "$(find parksim tests/fuzz -name '*.h' -newer "$object" | head -1)" ]; then
    mkdir -p "$(dirname "$object")"
    "$cxx" "${f[@]}" -c "$1" -o "$object"
  fi
}
export -f compile object_of
export nocov
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
mapfile -t realism < <(sources_under parksim/realism)
mapfile -t scenario < <(sources_under parksim/scenario)
# The results tables' readers and what they share (the episode record's fields, seals, ids,
# manifests, merge's sources).
# (An assignment, not mapfile: a name not found stops the script.)
list=$(src ResultsFile.cpp RowSeal.cpp TableVerify.cpp EpisodeRecord.cpp ExecutionDef.cpp \
  EpisodeParams.cpp SetValues.cpp SweepManifest.cpp Shard.cpp Merge.cpp)
mapfile -t tables <<<"$list"
list=$(src SweepSpecReader.cpp ComponentChoiceReader.cpp CommandLine.cpp EpisodeSetup.cpp \
  SetValues.cpp EpisodeRecord.cpp PlanScenario.cpp ExecutedFile.cpp EpisodeRequest.cpp \
  ExecutionDef.cpp)
mapfile -t spec <<<"$list"
declare -A sources
sources[world]="tests/fuzz/WorldReaderFuzz.cpp ${scenario[*]} ${realism[*]} ${core[*]}"
sources[plan]="tests/fuzz/PlanReaderFuzz.cpp $(src TrajectoryFile.cpp) ${core[*]}"
sources[spec]="tests/fuzz/SweepSpecFuzz.cpp ${spec[*]} ${scenario[*]} ${realism[*]} ${core[*]}"
sources[jsonl]="tests/fuzz/ResultsJsonlFuzz.cpp ${tables[*]} ${core[*]}"
sources[csv]="tests/fuzz/ResultsCsvFuzz.cpp ${tables[*]} ${core[*]}"
sources[manifest]="tests/fuzz/SweepManifestFuzz.cpp ${tables[*]} ${core[*]}"
sources[dict]="tests/fuzz/WorldDictFuzz.cpp ${scenario[*]} ${realism[*]} ${core[*]}"
readers=(world plan spec jsonl csv manifest dict)
libs_world=(-lyaml-cpp -lxml2 -lstb -lz)
libs_spec=(-lyaml-cpp -lxml2 -lstb -lz)
libs_dict=(-lyaml-cpp -lxml2 -lstb -lz)

echo "== compiling the readers for fuzzing (build-fuzz/obj/)"
for reader in "${readers[@]}"; do printf '%s\n' ${sources[$reader]}; done | sort -u |
  FLAGS="$flags_line" xargs -P "$(nproc)" -I{} bash -c 'eval "flags=($FLAGS)"; compile "$1"' _ {}
objects() { for f in "$@"; do object_of "$f"; done; }
for reader in "${readers[@]}"; do
  mapfile -t objs < <(objects ${sources[$reader]})
  libs_var="libs_$reader[@]"
  link "$reader" "${objs[@]}" -Wl,--gc-sections "${!libs_var}"
done

timeout_s=${FUZZ_TIMEOUT:-10}
common=(-timeout="$timeout_s" -rss_limit_mb=2048 -malloc_limit_mb=2048 -max_len=65536
        -print_final_stats=1)
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1}

if [ "${1:-}" = "--ci" ]; then
  # One reader's bounded run; its output goes to build-fuzz/ci-READER.log.
  ci_run() {
    set -euo pipefail
    local reader=$1
    # The table harnesses run ~40 inputs/s (64 KB tables, scanned twice under ASan), the other
    # readers hundreds: CI gives the tables a tenth of the mutations, so the bounded pass stays
    # within ~3 minutes on 2 cores. The long campaign below has no such limit.
    local runs=${FUZZ_RUNS:-20000}
    case "$reader" in jsonl | csv) runs=${FUZZ_TABLE_RUNS:-2000} ;; esac
    echo "== fuzz_$reader: corpus replay, then $runs mutations (seed 1)"
    local work
    work=$(mktemp -d)
    # The table harnesses' files (results.csv, sweep.json, worlds) go to memory when it can.
    PARKSIM_FUZZ_SCRATCH=$(mktemp -d /dev/shm/parksim-fuzz-XXXXXX 2>/dev/null || mktemp -d)
    export PARKSIM_FUZZ_SCRATCH
    # -runs counts mutations after the corpus; new inputs go to a scratch copy, and crash
    # reproducers into the build directory.
    cp tests/fuzz/corpus/$reader/* "$work"/
    # The outer timeout bounds the whole run even if libFuzzer's own handler hangs.
    # A safety bound on a slow machine: each reader stops after FUZZ_MAX_S seconds whatever
    # its count (20000 table mutations took ~470 s on a busy 2-core machine).
    local status=0
    timeout -k 10 600 "$out/fuzz_$reader" "${common[@]}" -seed=1 -runs="$runs" \
      -max_total_time="${FUZZ_MAX_S:-420}" \
      -artifact_prefix="$out/$reader-" "$work" 2>&1 | grep -v '^    #' | tail -n 12 ||
      status=$?
    rm -rf "$work" "$PARKSIM_FUZZ_SCRATCH"
    return $status
  }
  export -f ci_run
  export common_line
  common_line=$(printf '%q ' "${common[@]}")
  # The readers run side by side, one per core, the slow table harnesses first; each one's
  # output is printed whole once all have run, in this order.
  ci_order=(jsonl csv world plan spec manifest dict)
  failed=0
  printf '%s\n' "${ci_order[@]}" |
    xargs -P "$(nproc)" -I{} bash -c \
      'eval "common=($common_line)"; ci_run "$1" > "$out/ci-$1.log" 2>&1' _ {} || failed=1
  for reader in "${ci_order[@]}"; do cat "$out/ci-$reader.log"; done
  [ "$failed" = 0 ] || { echo "fuzz.sh: a reader failed (its output is above)" >&2; exit 1; }
  # The dict path's Python half, where the Python module is built (scripts/test.sh builds it).
  # (__init__.py is copied at configure time; the compiled module is what must exist.)
  if ls build/python/parksim/_parksim*.so >/dev/null 2>&1; then
    echo "== world_dict_fuzz.py: ${FUZZ_DICT_RUNS:-2000} mutated world dicts (seed 1)"
    timeout -k 10 600 /usr/bin/python3 tests/fuzz/world_dict_fuzz.py build/python worlds \
      "${FUZZ_DICT_RUNS:-2000}" 1
  else
    echo "== world_dict_fuzz.py: skipped (no Python module in build/python; scripts/test.sh builds it)"
  fi
  exit 0
fi

reader=${1:?usage: scripts/fuzz.sh --ci | scripts/fuzz.sh world|plan|spec|jsonl|csv|manifest|dict [libFuzzer args...]}
[ -n "${sources[$reader]:-}" ] || { echo "fuzz.sh: no reader '$reader' (${readers[*]})" >&2; exit 2; }
if [ -z "${PARKSIM_FUZZ_SCRATCH:-}" ]; then
  PARKSIM_FUZZ_SCRATCH=$out/scratch-$reader
  mkdir -p "$PARKSIM_FUZZ_SCRATCH"
  export PARKSIM_FUZZ_SCRATCH
fi
shift
mkdir -p "$out/corpus-$reader"
exec "$out/fuzz_$reader" "${common[@]}" -artifact_prefix="$out/$reader-" "$@" \
  "$out/corpus-$reader" "tests/fuzz/corpus/$reader"
