# Sweep throughput: episodes/s with 1 and 2 workers and the per-episode overhead outside planning
# and simulation (docs/sweeps.md, "Throughput").
include_guard(GLOBAL)
add_executable(bench_sweep ${CMAKE_CURRENT_LIST_DIR}/bench_sweep.cpp)
target_link_libraries(bench_sweep PRIVATE parksim_sweep)
target_compile_definitions(bench_sweep PRIVATE PARKSIM_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
parksim_target_defaults(bench_sweep)
