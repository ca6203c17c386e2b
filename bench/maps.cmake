# Maps in worlds (issue 32): a 1,000 x 1,000-cell ROS map read, merged and in Bullet, and
# planned; the warehouse world planned; a 500-shape SVG read; each beside a hand-written lot of
# the same obstacles (docs/benchmarks.md, "Maps").
include_guard(GLOBAL)
add_executable(bench_maps ${CMAKE_CURRENT_LIST_DIR}/bench_maps.cpp)
target_link_libraries(bench_maps PRIVATE parksim_scenario parksim_collision parksim_sim
                                         parksim_planner benchmark::benchmark
                                         benchmark::benchmark_main)
parksim_target_defaults(bench_maps)
