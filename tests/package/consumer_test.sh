#!/usr/bin/env bash
# Installs the build tree into a temporary prefix, builds examples/consumer against it with
# find_package(parksim), and runs it on head_in: the installed package is complete and usable.
# Usage: consumer_test.sh SOURCE_DIR BUILD_DIR
set -euo pipefail
src=$1
build=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

cmake --install "$build" --prefix "$tmp/prefix" >/dev/null
test -f "$tmp/prefix/include/parksim/sim/episode/Episode.h"
test -x "$tmp/prefix/bin/parksim"
ls "$tmp"/prefix/lib*/cmake/parksim/parksimConfigVersion.cmake >/dev/null
# The OMPL plugin, which the consumer's default plan loads (its smoothing uses Reeds-Shepp
# curves) through the run path the package gives it: nothing in the build tree is reachable.
ls "$tmp"/prefix/lib*/parksim/libparksim_ompl_plugin.so >/dev/null
# The pages' npm libraries, built into parksim_pages, are installed beside it with their
# licences (docs/pages.md); their packages stay out of the headers.
test -f "$tmp/prefix/share/parksim/pages/uplot/LICENSE"
test -f "$tmp/prefix/share/parksim/pages/tabulator-tables/dist/js/tabulator.min.js"
test -f "$tmp/prefix/include/parksim/pages/EpisodePage.h"
test ! -e "$tmp/prefix/include/parksim/pages/web/node_modules"

generator=()
command -v ninja >/dev/null && generator=(-G Ninja)
launcher=()
[ -n "${CMAKE_CXX_COMPILER_LAUNCHER:-}" ] &&
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER="$CMAKE_CXX_COMPILER_LAUNCHER")
cmake -S "$src/examples/consumer" -B "$tmp/consumer" "${generator[@]}" "${launcher[@]}" \
  -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$tmp/prefix" >/dev/null
cmake --build "$tmp/consumer" >/dev/null
"$tmp/consumer/park" "$src/worlds/head_in.yaml" 1

# The command-line front-ends' support library is exported too: a tool of the consumer's own
# links parksim::cli (and CLI11 through it) and runs.
mkdir -p "$tmp/cli-probe"
cat >"$tmp/cli-probe/CMakeLists.txt" <<'CMAKE'
cmake_minimum_required(VERSION 3.22)
project(cli_probe LANGUAGES CXX)
find_package(parksim 0.3 REQUIRED)
add_executable(probe main.cpp)
target_link_libraries(probe PRIVATE parksim::cli)
CMAKE
cat >"$tmp/cli-probe/main.cpp" <<'CPP'
#include <parksim/cli/TerminalText.h>
#include <cstdio>
int main() { std::puts(parksim::cli::printable("a\tb").c_str()); }
CPP
cmake -S "$tmp/cli-probe" -B "$tmp/cli-probe/build" "${generator[@]}" "${launcher[@]}" \
  -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$tmp/prefix" >/dev/null
cmake --build "$tmp/cli-probe/build" >/dev/null
test "$("$tmp/cli-probe/build/probe")" = 'a\x09b'

# A plugin project built against the installed package (examples/plugins): its planner and
# controller run in plan, run, a sweep and parksim-bench (docs/your-code.md).
parksim=$tmp/prefix/bin/parksim
cmake -S "$src/examples/plugins" -B "$tmp/plugins" "${generator[@]}" "${launcher[@]}" \
  -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$tmp/prefix" >/dev/null
cmake --build "$tmp/plugins" >/dev/null
plugin=$tmp/plugins/libparksim_example_plugins.so
"$parksim" plan "$src/worlds/parallel.yaml" --plugin "$plugin" --planner example -q --out "$tmp/p"
"$parksim" run "$src/worlds/parallel.yaml" --plugin "$plugin" --planner example \
  --controller pure-pursuit -q --out "$tmp/r"
grep -q '"provenance.plugins": "parksim-examples 1.0.0 ' "$tmp/r/metrics.json"
cat >"$tmp/spec.yaml" <<SPEC
format: parksim-sweep/1
name: plugin
worlds: [$src/worlds/parallel.yaml]
plugins: [$plugin]
planners: [time-a-star, example]
controllers: [tracking, pure-pursuit]
SPEC
"$parksim" sweep "$tmp/spec.yaml" --out "$tmp/sweep" >/dev/null
test "$(wc -l <"$tmp/sweep/results.jsonl")" -eq 4
if [ -x "$build/bench/parksim-bench" ]; then
  "$build/bench/parksim-bench" "$src/worlds/parallel.yaml" --plugin "$plugin" \
    --planners example,time-a-star --seeds 2 -q >/dev/null
fi

# Your controller's CI in ten minutes (examples/controller-ci): a project of its own builds its
# controller, stores a baseline, passes against it, and fails (exit 4) a worse controller.
cp -r "$src/examples/controller-ci" "$tmp/ci"
rm -rf "$tmp/ci/build" "$tmp/ci/out" "$tmp/ci/baseline"
export PARKSIM=$parksim CMAKE_PREFIX_PATH=$tmp/prefix
"$tmp/ci/ci.sh" refresh >/dev/null
"$tmp/ci/ci.sh" check >/dev/null
grep -q '<testsuite' "$tmp/ci/out/sweep.xml"
# The same controller with its corrections turned down: a regression.
sed 's/^controllers: .*/controllers: [{name: my-controller, params: {speed_gain: 0, heading_gain: 0.2, lateral_gain: 0}}]/' \
  "$tmp/ci/sweep.yaml" >"$tmp/ci/worse.yaml"
status=0
SPEC=worse.yaml "$tmp/ci/ci.sh" check >/dev/null || status=$?
test "$status" -eq 4
unset PARKSIM CMAKE_PREFIX_PATH

# The version file refuses another minor version.
cat >"$tmp/version.cmake" <<'CMAKE'
find_package(parksim 0.4 QUIET)
if(parksim_FOUND)
  message(FATAL_ERROR "find_package(parksim 0.4) accepted version ${parksim_VERSION}")
endif()
CMAKE
cmake -DCMAKE_PREFIX_PATH="$tmp/prefix" -P "$tmp/version.cmake"
echo "consumer built and ran against the installed package"
