# Simulation benchmark: real-time factor of the dynamics alone and wall time of a whole episode
# (plan + simulate + metrics) on the study worlds (docs/simulation.md, "Benchmark").
include_guard(GLOBAL)
add_executable(bench_episode ${CMAKE_CURRENT_LIST_DIR}/bench_episode.cpp)
target_link_libraries(bench_episode PRIVATE parksim_sim parksim_results parksim_planner parksim_collision
                                            parksim_scenario benchmark::benchmark)
target_compile_definitions(bench_episode PRIVATE PARKSIM_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
parksim_target_defaults(bench_episode)
