# A sweep with its workers forced to threads or processes, for the plugin overhead benchmark
# (bench/plugin_overhead.sh; docs/benchmarks.md, "Plugin overhead").
include_guard(GLOBAL)
add_executable(bench_plugin_sweep ${CMAKE_CURRENT_LIST_DIR}/bench_plugin_sweep.cpp)
target_link_libraries(bench_plugin_sweep PRIVATE parksim_sweep)
parksim_target_defaults(bench_plugin_sweep)
