# MuJoCo side by side with parksim (docs/simulation.md, "MuJoCo side by side"): the study's plan
# driven open loop in an equivalent MuJoCo model and in parksim, in one run. Optional: built
# only when MuJoCo is found (Debian: libmujoco-dev, in scripts/install-deps.sh's list of
# packages only the benchmarks need).
include_guard(GLOBAL)
# The header and the library, not Debian's mujocoConfig.cmake: its imported target names
# /usr/include/libqhull_r/, which only libqhull-dev installs, and CMake refuses the target
# without it.
find_path(PARKSIM_MUJOCO_INCLUDE_DIR mujoco/mujoco.h)
find_library(PARKSIM_MUJOCO_LIBRARY mujoco)
if(NOT PARKSIM_MUJOCO_INCLUDE_DIR OR NOT PARKSIM_MUJOCO_LIBRARY)
  message(STATUS "Without bench_mujoco: MuJoCo not found (Debian package libmujoco-dev)")
  return()
endif()
add_executable(bench_mujoco ${CMAKE_CURRENT_LIST_DIR}/bench_mujoco.cpp)
target_include_directories(bench_mujoco SYSTEM PRIVATE ${PARKSIM_MUJOCO_INCLUDE_DIR})
target_link_libraries(bench_mujoco PRIVATE parksim_sim parksim_scenario parksim_results ${PARKSIM_MUJOCO_LIBRARY})
target_compile_definitions(bench_mujoco PRIVATE PARKSIM_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
parksim_target_defaults(bench_mujoco)
