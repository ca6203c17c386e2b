# Plan quality and planning time against the best known (bench_planning.cpp; issue 18,
# docs/benchmarks.md "Plan quality against the best known").
include_guard(GLOBAL)
include(${CMAKE_CURRENT_LIST_DIR}/planning.cmake)
add_executable(bench_planning ${CMAKE_CURRENT_LIST_DIR}/bench_planning.cpp)
target_link_libraries(bench_planning PRIVATE parksim_plan_bench parksim_scenario)
parksim_target_defaults(bench_planning)
