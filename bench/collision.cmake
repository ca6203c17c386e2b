# Footprint-query benchmark: BulletCollisionWorld::isFree against hand-written separating-axis
# tests on the same poses (docs/benchmarks.md, "Footprint queries").
include_guard(GLOBAL)
add_executable(bench_collision ${CMAKE_CURRENT_LIST_DIR}/bench_collision.cpp)
target_link_libraries(bench_collision PRIVATE parksim_collision parksim_scenario benchmark::benchmark
                                              benchmark::benchmark_main)
target_compile_definitions(bench_collision PRIVATE PARKSIM_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
parksim_target_defaults(bench_collision)
