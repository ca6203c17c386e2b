# Pages: what writing an episode's and a sweep's page costs beside the episode (docs/pages.md).
# The pages in a browser are measured by bench/pages/bench_pages.py.
include_guard(GLOBAL)
add_executable(bench_pages ${CMAKE_CURRENT_LIST_DIR}/bench_pages.cpp)
target_link_libraries(bench_pages PRIVATE parksim_pages parksim_pipeline parksim_scenario parksim_sweep
                                          benchmark::benchmark)
target_compile_definitions(bench_pages PRIVATE PARKSIM_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
parksim_target_defaults(bench_pages)
