# Planning benchmark (parksim bench): runs parksim's planners, checks every path with parksim's
# exact path check, and writes bench.csv and the summary tables. No OMPL here; see ompl.cmake.
include_guard(GLOBAL)
add_library(parksim_plan_bench
  ${CMAKE_CURRENT_LIST_DIR}/planning/BenchCsv.cpp
  ${CMAKE_CURRENT_LIST_DIR}/planning/BenchSummary.cpp
  ${CMAKE_CURRENT_LIST_DIR}/planning/BestKnown.cpp
  ${CMAKE_CURRENT_LIST_DIR}/planning/ParksimRuns.cpp
  ${CMAKE_CURRENT_LIST_DIR}/planning/PathCheck.cpp
  ${CMAKE_CURRENT_LIST_DIR}/planning/PlanShape.cpp)
target_link_libraries(parksim_plan_bench PUBLIC parksim_planner parksim_collision)
parksim_target_defaults(parksim_plan_bench)
