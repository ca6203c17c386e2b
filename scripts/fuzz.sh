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
#   scripts/fuzz.sh --build                  only build the fuzzers (scripts/test.sh builds them
#                                            while the sanitizer tests run)
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
# The sources are compiled in groups, each group as one translation unit (a unity build: the
# headers and the templates its files share are compiled once), against a precompiled header of
# the third-party headers every library may include (cmake/PchCommon.h); a reader links whole
# groups. Names at file scope must therefore be unique within a group: a second one is a compile
# error naming both files. This took the build's compiles from 177 to about 90 CPU seconds
# (docs/building.md).
declare -A group
# The readers need the core library but not its build-provenance file (a configured header).
group[core]=$(sources_under parksim/core | grep -v '/Provenance\.cpp$')
# The world reader, with its realism: section checked by the Bullet-free parksim_realism library
# (parksim/realism/, all of it).
group[scenario]=$(sources_under parksim/scenario; sources_under parksim/realism)
# The results tables' readers and what they share (the episode record's fields, seals, ids,
# manifests, merge's sources; the plan's status and phase names, PlanResult.cpp).
group[tables]=$(src ResultsFile.cpp RowSeal.cpp TableVerify.cpp EpisodeRecord.cpp ExecutionDef.cpp \
  EpisodeParams.cpp SetValues.cpp SweepManifest.cpp Shard.cpp Merge.cpp PlanResult.cpp)
# The sweep-spec reader (with the tables group: the record's fields, the axes' values).
group[spec]=$(src SweepSpecReader.cpp ComponentChoiceReader.cpp CommandLine.cpp EpisodeSetup.cpp \
  EpisodeRequest.cpp)
group[trajectory]=$(src TrajectoryFile.cpp)
# The sweep-spec reader takes its name lists (planners, steerings, timings) from PlanScenario.cpp,
# whose other functions need the whole planner (OMPL, Bullet), and its record format's names
# from ExecutedFile.cpp (the record writers). The fuzzer's coverage tables keep every
# instrumented function alive, so these two are compiled without them (still with ASan and
# UBSan; each alone, without the precompiled header, which has them) and --gc-sections drops
# what the spec reader does not call.
group[plan_scenario]=$(src PlanScenario.cpp)
group[executed_file]=$(src ExecutedFile.cpp)
nocov=" plan_scenario executed_file "
# One harness each (the readers' entry points, tests/fuzz/).
declare -A harness=([world]=WorldReaderFuzz [plan]=PlanReaderFuzz [spec]=SweepSpecFuzz
                    [jsonl]=ResultsJsonlFuzz [csv]=ResultsCsvFuzz [manifest]=SweepManifestFuzz
                    [dict]=WorldDictFuzz)
for reader in "${!harness[@]}"; do group[fuzz_$reader]=tests/fuzz/${harness[$reader]}.cpp; done
declare -A groups=(
  [world]="scenario core" [dict]="scenario core" [plan]="trajectory core"
  [spec]="spec plan_scenario executed_file tables scenario core"
  [jsonl]="tables core" [csv]="tables core" [manifest]="tables core")
readers=(world plan spec jsonl csv manifest dict)
libs_world=(-lyaml-cpp -lxml2 -lstb -lz)
libs_spec=(-lyaml-cpp -lxml2 -lstb -lz)
libs_dict=(-lyaml-cpp -lxml2 -lstb -lz)

pch=$out/obj/PchCommon.h.pch
compile() {  # compile GROUP: its unity file into build-fuzz/obj/GROUP.o, when out of date
  local name=$1 object=$out/obj/$1.o unity=$out/unity/$1.cpp f=("${flags[@]}")
  case "$nocov" in
    *" $name "*) f=("${f[@]/-fsanitize=fuzzer,address,undefined/-fsanitize=address,undefined}") ;;
    *) f+=(-include-pch "$pch" -include cmake/PchCommon.h) ;;
  esac
  local file
  for file in $(sed -n 's/^#include "\(.*\)"$/\1/p' "$unity"); do
    [ "$file" -nt "$object" ] && rm -f "$object"
  done
  if [ ! -f "$object" ] || [ "$unity" -nt "$object" ] || [ "$pch" -nt "$object" ] ||
     [ -n "$(find parksim tests/fuzz -name '*.h' -newer "$object" | head -1)" ]; then
    "$cxx" "${f[@]}" -c "$unity" -o "$object"
  fi
}
export -f compile
export out cxx pch nocov
flags_line=$(printf '%q ' "${flags[@]}")

# The compilers' memory on transparent huge pages, as in scripts/build.sh (14 % less CPU here).
export GLIBC_TUNABLES=${GLIBC_TUNABLES:+$GLIBC_TUNABLES:}glibc.malloc.hugetlb=1
echo "== compiling the readers for fuzzing (build-fuzz/obj/)"
mkdir -p "$out/obj" "$out/unity"
# A group's unity file is written again only when its list of sources changed.
for name in "${!group[@]}"; do
  text=$(printf '#include "%s"\n' ${group[$name]})
  [ "$(cat "$out/unity/$name.cpp" 2>/dev/null)" = "$text" ] || echo "$text" > "$out/unity/$name.cpp"
done
if [ ! -f "$pch" ] || [ cmake/PchCommon.h -nt "$pch" ]; then
  "$cxx" "${flags[@]}" -fpch-instantiate-templates -x c++-header cmake/PchCommon.h -o "$pch"
fi
# The largest groups first, on all cores.
for name in "${!group[@]}"; do echo "$(wc -w <<<"${group[$name]}") $name"; done | sort -rn |
  cut -d' ' -f2 |
  FLAGS="$flags_line" xargs -P "$(nproc)" -I{} bash -c 'eval "flags=($FLAGS)"; compile "$1"' _ {}

# lld where it is installed, as the CMake builds (cmake/TargetDefaults.cmake).
linker=()
command -v ld.lld >/dev/null && linker=(-fuse-ld=lld)
link() {  # link READER: its harness and groups, into build-fuzz/fuzz_READER
  local reader=$1 objs=("$out/obj/fuzz_$1.o") name
  for name in ${groups[$reader]}; do objs+=("$out/obj/$name.o"); done
  local libs_var="libs_$reader[@]"
  echo "== linking $out/fuzz_$reader"
  "$cxx" "${flags[@]}" "${objs[@]}" "${linker[@]}" -Wl,--gc-sections "${!libs_var}" \
    -o "$out/fuzz_$reader"
}
for reader in "${readers[@]}"; do
  link "$reader"
done
[ "${1:-}" = --build ] && exit 0

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
[ -n "${groups[$reader]:-}" ] || { echo "fuzz.sh: no reader '$reader' (${readers[*]})" >&2; exit 2; }
if [ -z "${PARKSIM_FUZZ_SCRATCH:-}" ]; then
  PARKSIM_FUZZ_SCRATCH=$out/scratch-$reader
  mkdir -p "$PARKSIM_FUZZ_SCRATCH"
  export PARKSIM_FUZZ_SCRATCH
fi
shift
mkdir -p "$out/corpus-$reader"
exec "$out/fuzz_$reader" "${common[@]}" -artifact_prefix="$out/$reader-" "$@" \
  "$out/corpus-$reader" "tests/fuzz/corpus/$reader"
