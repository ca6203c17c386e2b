# OMPL side of the planning benchmark: OMPL's planners on parksim's footprint checker, each run
# in a forked child process (OMPL's RNG seed is process-wide), and OMPL's benchmark log format.
# parksim_ompl_bench is what parksim-bench links (parksim_bench.cmake); it brings
# parksim_plan_bench along.
include_guard(GLOBAL)
include(${CMAKE_CURRENT_LIST_DIR}/planning.cmake)

# Debian's omplConfig.cmake defines variables only. OMPL_LIBRARIES also lists Boost libraries
# that exist only with the Boost -dev packages installed; libompl links Boost itself, so keep
# libompl alone. OMPL_INCLUDE_DIRS adds /usr/include itself: use OMPL_INCLUDE_DIR.
find_package(ompl REQUIRED)
set(parksim_ompl_libraries ${OMPL_LIBRARIES})
list(FILTER parksim_ompl_libraries INCLUDE REGEX "libompl\\.")

add_library(parksim_ompl_bench
  ${CMAKE_CURRENT_LIST_DIR}/ompl/OmplPlanners.cpp)
target_include_directories(parksim_ompl_bench SYSTEM PRIVATE ${OMPL_INCLUDE_DIR})
target_link_libraries(parksim_ompl_bench PUBLIC parksim_plan_bench
                                         PRIVATE ${parksim_ompl_libraries})

parksim_target_defaults(parksim_ompl_bench)
