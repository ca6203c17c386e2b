# parksim-bench: the planning benchmark as a program of its own (docs/benchmarks.md): every
# parksim planner and, with --ompl, OMPL's on the same footprint checker, paths checked exactly,
# bench.csv and summary tables. It stands beside the parksim command line on the library.
include_guard(GLOBAL)
include(${CMAKE_CURRENT_LIST_DIR}/ompl.cmake)
add_executable(parksim_bench ${CMAKE_CURRENT_LIST_DIR}/parksim_bench.cpp)
set_target_properties(parksim_bench PROPERTIES OUTPUT_NAME parksim-bench)
target_link_libraries(parksim_bench PRIVATE parksim_ompl_bench parksim_results parksim_cli parksim_scenario)
parksim_target_defaults(parksim_bench)
install(TARGETS parksim_bench RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
