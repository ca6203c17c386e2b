# What every parksim target gets: call parksim_target_defaults(<target>) once in the CMakeLists
# that defines it. Warnings, and the two things that make a cold build fast on 2 cores
# (measurements and commands in docs/building.md):
#
# - Precompiled headers. Most of a parksim translation unit's compile time is spent parsing the
#   same third-party headers (the standard library, Eigen, nlohmann/json, yaml-cpp, GoogleTest,
#   CLI11, pybind11). They are parsed once per build into a precompiled header that the
#   targets share (REUSE_FROM): one for libraries (-fPIC), one for test programs (-fPIE, with
#   GoogleTest); programs that use CLI11 and the Python module get their own, with CLI11 and
#   pybind11. GCC rejects a precompiled header made with other code-generation flags
#   (-Winvalid-pch warns) and then parses the headers as usual: a build is never wrong, only slower.
# - Unity builds: the sources of a library or program are compiled in batches of
#   PARKSIM_UNITY_BATCH_SIZE, so the headers and the templates many files of a target use are
#   compiled and optimised once per batch, not once per file. Names at file scope (anonymous
#   namespaces, static functions) must then be unique within a target: a second definition of one
#   is a compile error ("redefinition of ...") naming both files. Rename one, or add the file to
#   PARKSIM_UNITY_SKIP below. Test programs are batched too, in batches of
#   PARKSIM_TEST_UNITY_BATCH_SIZE; their files share helper names more often (`errorOf`, `kWorld`):
#   a test file whose helpers would meet another file's keeps them in a namespace named after
#   the file (e.g. `parksim::world_test`) instead of an anonymous one, and no test file is
#   compiled alone.
#
# Both are on by default and off with -DPARKSIM_PCH=OFF / -DPARKSIM_UNITY=OFF (e.g. to check that
# every file includes what it uses, which a precompiled header can hide).

option(PARKSIM_PCH "Precompile the heavy third-party headers (docs/building.md)" ON)
option(PARKSIM_UNITY "Compile each target's sources in batches (unity build; docs/building.md)" ON)
set(PARKSIM_UNITY_BATCH_SIZE 6 CACHE STRING
    "Sources per unity batch: larger builds faster cold, smaller rebuilds less after an edit")
set(PARKSIM_TEST_UNITY_BATCH_SIZE 8 CACHE STRING
    "Test sources per unity batch (test programs; docs/building.md)")
# The optimisation of cold code: the test programs (but those marked OPTIMIZED in
# tests/CMakeLists.txt), the test plugins, and the libraries and program marked COLD
# (parksim_target_defaults below: the command line, result files, pages, reports, sweeps, user
# code's loading; code that runs once per episode or per file, not per step or per query). The
# flag comes after the build type's (the last -O wins) and goes into the precompiled headers
# these targets share; empty keeps the build type's. The sanitizer pass of scripts/test.sh sets
# -O0, the rest staying at -O1: their compile time is mostly templates (GoogleTest's,
# nlohmann/json's, CLI11's, Eigen's) being optimised (render_tests: 27 CPU s at -O1, 10 at -O0).
# Test programs whose tests compute in their own code are OPTIMIZED: at -O0 they ran 2 to 8
# times slower (docs/building.md, "CI in 10 minutes").
set(PARKSIM_COLD_OPTIMIZATION "" CACHE STRING
    "Optimisation flag of cold code (test programs, targets marked COLD), e.g. -O0 (empty: the build type's)")
# One or more flags ("-O0 -g0" too): the cache string as a list, for every use below.
separate_arguments(PARKSIM_COLD_OPTIMIZATION UNIX_COMMAND "${PARKSIM_COLD_OPTIMIZATION}")
# Sources compiled on their own in a unity build (paths relative to the top folder), each with the
# reason: mostly a name it shares with another file of its target.
set(PARKSIM_UNITY_SKIP
  parksim/planner/tree/ShortcutSmoother.cpp   # kCostEpsilonM, also in TreePlanner.cpp
  parksim/renders/image/PngEncoderStb.cpp     # stb_image_write's statics, also in PngEncoder.cpp
  # Added after the planner's batches were laid out: alone, it leaves them as they were
  # (TreeSearch.h's and TimeAStarSearch.cpp's Clock would otherwise meet in one batch).
  parksim/planner/search/ReachableBudget.cpp
  # The same for the car planner's files (docs/planning.md, "Cars").
  parksim/planner/search/CarAStar.cpp
  parksim/planner/search/CarAStarPlanner.cpp
  parksim/planner/motion/CarPath.cpp
  parksim/planner/motion/CarPlanAlong.cpp
  parksim/planner/motion/CarTimeCost.cpp
  parksim/planner/motion/CarTiming.cpp
  parksim/planner/motion/ClearanceValidator.cpp
  # setCombinations, also in EpisodeExpansion.cpp: they meet in batches of 16 (scripts/test.sh).
  parksim/sweep/spec/SweepSpecReader.cpp
  # Not a name: it includes ProvenanceGit.h, which a commit or a first edit rewrites; alone,
  # only this file is compiled again then, not its batch.
  parksim/core/system/Provenance.cpp
)

# The linker: lld where it is installed (scripts/install-deps.sh installs it), else the
# compiler's default (GNU ld). The sanitizer build's 27 largest programs linked in 18 CPU s with
# lld against 46 with GNU ld (docs/building.md, "Shards, lld, huge pages"); a program's
# computations, and so its outputs, do not depend on the linker.
option(PARKSIM_LLD "Link with lld where it is installed (faster links)" ON)
if(PARKSIM_LLD)
  include(CheckLinkerFlag)
  check_linker_flag(CXX -fuse-ld=lld PARKSIM_HAVE_LLD)
  if(PARKSIM_HAVE_LLD)
    add_link_options(-fuse-ld=lld)
  endif()
endif()

if(PARKSIM_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all)
  add_link_options(-fsanitize=address,undefined)
  # Programs linked at fixed addresses (-no-pie): the sanitized `parksim` as a position-
  # independent executable carries 485,000 relative relocations, which the dynamic loader
  # applies, faulting in their pages, each time it starts (hundreds of times in the CLI tests):
  # 0.134 -> 0.112 CPU s a start (docs/building.md, "Shards, lld, huge pages").
  add_link_options($<$<STREQUAL:$<TARGET_PROPERTY:TYPE>,EXECUTABLE>:-no-pie>)
endif()

# The headers every precompiled header starts with: the standard headers parksim includes most,
# Eigen, nlohmann/json and yaml-cpp (the list, and why Bullet and OMPL are not in it, is in the
# file; scripts/fuzz.sh precompiles the same file for the fuzzers).
set(PARKSIM_PCH_COMMON ${PROJECT_SOURCE_DIR}/cmake/PchCommon.h)

# A target whose precompiled header others reuse: its flags are those of the targets that reuse
# it (C++20, the warnings: -Wpedantic changes predefined macros the header checks).
function(_parksim_pch_host name kind)
  if(kind STREQUAL "exe")
    # -fPIE: a program (linked, never run). No compile definitions of its own: GCC rejects a
    # precompiled header made with a macro that the file using it does not define.
    add_executable(${name} EXCLUDE_FROM_ALL ${PROJECT_SOURCE_DIR}/cmake/PchHostMain.cpp)
  else()
    add_library(${name} OBJECT EXCLUDE_FROM_ALL ${PROJECT_SOURCE_DIR}/cmake/PchHost.cpp)
  endif()
  target_compile_options(${name} PRIVATE -Wall -Wextra -Wpedantic -Wshadow)
  target_link_libraries(${name} PRIVATE ${ARGN})
  set_target_properties(${name} PROPERTIES UNITY_BUILD OFF)
endfunction()

# Called once from the top-level CMakeLists, after the dependencies are found.
function(parksim_define_pch_hosts)
  if(NOT PARKSIM_PCH)
    return()
  endif()
  # A precompiled header is used only with the optimisation it was made with: where
  # PARKSIM_COLD_OPTIMIZATION is set, cold targets share one made at it (parksim_pch_lib_cold,
  # and parksim_pch_test for the test programs), the others one at the build type's
  # (parksim_pch_lib, parksim_pch_test_optimized for test programs marked OPTIMIZED).
  set(lib_deps Eigen3::Eigen nlohmann_json::nlohmann_json yaml-cpp)
  set(lib_headers ${PARKSIM_PCH_COMMON})
  _parksim_pch_host(parksim_pch_lib lib ${lib_deps})
  target_precompile_headers(parksim_pch_lib PRIVATE ${lib_headers})
  if(PARKSIM_COLD_OPTIMIZATION)
    _parksim_pch_host(parksim_pch_lib_cold lib ${lib_deps})
    target_precompile_headers(parksim_pch_lib_cold PRIVATE ${lib_headers})
    target_compile_options(parksim_pch_lib_cold PRIVATE ${PARKSIM_COLD_OPTIMIZATION})
  endif()
  if(TARGET GTest::gtest_main)
    set(test_deps ${lib_deps} GTest::gtest_main GTest::gmock)
    set(test_headers ${PARKSIM_PCH_COMMON} <gtest/gtest.h> <gmock/gmock.h>)
    _parksim_pch_host(parksim_pch_test exe ${test_deps})
    target_precompile_headers(parksim_pch_test PRIVATE ${test_headers})
    target_compile_options(parksim_pch_test PRIVATE ${PARKSIM_COLD_OPTIMIZATION})
    if(PARKSIM_COLD_OPTIMIZATION)
      _parksim_pch_host(parksim_pch_test_optimized exe ${test_deps})
      target_precompile_headers(parksim_pch_test_optimized PRIVATE ${test_headers})
    endif()
  endif()
endfunction()

# The precompiled header of one target, chosen when its directory is done (its
# target_link_libraries may come after parksim_target_defaults).
function(_parksim_apply_pch target)
  get_target_property(type ${target} TYPE)
  get_target_property(libs ${target} LINK_LIBRARIES)
  if(NOT libs)
    set(libs "")
  endif()
  get_target_property(kind ${target} PARKSIM_PCH_KIND)
  if(kind STREQUAL "test" AND TARGET parksim_pch_test)
    target_precompile_headers(${target} REUSE_FROM parksim_pch_test)
  elseif(kind STREQUAL "test_optimized" AND TARGET parksim_pch_test_optimized)
    target_precompile_headers(${target} REUSE_FROM parksim_pch_test_optimized)
  elseif(type STREQUAL "MODULE_LIBRARY" AND target STREQUAL "parksim_python")
    # The Python module: Python.h must come before the standard headers; -fvisibility=hidden.
    set(headers <pybind11/pybind11.h> <pybind11/numpy.h> <pybind11/stl.h> ${PARKSIM_PCH_COMMON})
    if("CLI11::CLI11" IN_LIST libs)
      list(APPEND headers <CLI/CLI.hpp>)
    endif()
    target_precompile_headers(${target} PRIVATE ${headers})
  elseif("CLI11::CLI11" IN_LIST libs)
    # The command line: CLI11 is header-only and its headers take ~8 s to parse per file.
    target_precompile_headers(${target} PRIVATE ${PARKSIM_PCH_COMMON} <CLI/CLI.hpp>)
  elseif(type MATCHES "^(STATIC|SHARED|OBJECT)_LIBRARY$" AND kind STREQUAL "cold"
         AND TARGET parksim_pch_lib_cold)
    target_precompile_headers(${target} REUSE_FROM parksim_pch_lib_cold)
  elseif(type MATCHES "^(STATIC|SHARED|OBJECT)_LIBRARY$")
    target_precompile_headers(${target} REUSE_FROM parksim_pch_lib)
  endif()
  # Other programs (benchmarks, examples) and the OMPL plugin are a file or two: nothing to share.
endfunction()

function(parksim_target_defaults target)
  # COLD: compiled at PARKSIM_COLD_OPTIMIZATION (above).
  cmake_parse_arguments(ARG "COLD" "" "" ${ARGN})
  if(ARG_COLD)
    set_target_properties(${target} PROPERTIES PARKSIM_PCH_KIND cold)
    target_compile_options(${target} PRIVATE ${PARKSIM_COLD_OPTIMIZATION})
  endif()
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow)
  if(PARKSIM_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
  # Shared and static libraries compile alike (no <target>_EXPORTS definition; parksim has no
  # export macros), so a compiler cache serves one from the other (scripts/test.sh).
  set_target_properties(${target} PROPERTIES DEFINE_SYMBOL "")
  get_target_property(kind ${target} PARKSIM_PCH_KIND)
  if(PARKSIM_UNITY)
    set(batch ${PARKSIM_UNITY_BATCH_SIZE})
    if(kind MATCHES "^test")
      set(batch ${PARKSIM_TEST_UNITY_BATCH_SIZE})
    endif()
    set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE ${batch})
    # A batch includes its sources like headers, and GCC then warns that a class of one (a
    # parksim type with a member from the file's anonymous namespace) could be seen elsewhere.
    target_compile_options(${target} PRIVATE $<$<CXX_COMPILER_ID:GNU>:-Wno-subobject-linkage>)
    get_target_property(sources ${target} SOURCES)
    foreach(source IN LISTS sources)
      get_filename_component(path ${source} ABSOLUTE)
      file(RELATIVE_PATH path ${PROJECT_SOURCE_DIR} ${path})
      if(path IN_LIST PARKSIM_UNITY_SKIP)
        set_source_files_properties(${source} PROPERTIES SKIP_UNITY_BUILD_INCLUSION ON)
      endif()
    endforeach()
  endif()
  if(PARKSIM_PCH)
    # Deferred to the end of the calling directory; the argument is expanded now.
    cmake_language(EVAL CODE "cmake_language(DEFER CALL _parksim_apply_pch [[${target}]])")
  endif()
endfunction()
