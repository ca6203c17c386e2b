# A controller that is a process against the same law built in: episodes under `lab` and the
# per-tick round trip (docs/your-code.md, "Speed").
include_guard(GLOBAL)
add_executable(bench_command ${CMAKE_CURRENT_LIST_DIR}/bench_command.cpp)
target_link_libraries(bench_command PRIVATE parksim_command parksim_sim parksim_planner
                                            parksim_collision parksim_scenario benchmark::benchmark)
target_compile_definitions(bench_command PRIVATE PARKSIM_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
parksim_target_defaults(bench_command)
