# The installed package: libraries, headers under include/parksim/, the parksim executable (app/)
# and parksimConfig.cmake, so that a consumer writes
#   find_package(parksim 0.3 REQUIRED)
#   target_link_libraries(app PRIVATE parksim::parksim)   # or parksim::sim, parksim::planner...
# and gets the include directory, C++20 and the dependencies through the targets.

include(CMakePackageConfigHelpers)

set(PARKSIM_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/parksim)

# Module targets keep their build names (parksim_sim) and are exported as parksim::sim; the
# aliases give a project that adds parksim as a subdirectory the same names.
set(parksim_modules core realism scenario collision planner sim plugin rl results command render
    pages
    pipeline sweep report compare)
foreach(module IN LISTS parksim_modules)
  set_target_properties(parksim_${module} PROPERTIES EXPORT_NAME ${module})
  add_library(parksim::${module} ALIAS parksim_${module})
endforeach()

# parksim::parksim: every module.
add_library(parksim_library INTERFACE)
set_target_properties(parksim_library PROPERTIES EXPORT_NAME parksim)
foreach(module IN LISTS parksim_modules)
  target_link_libraries(parksim_library INTERFACE parksim_${module})
endforeach()
add_library(parksim::parksim ALIAS parksim_library)

# parksim::cli: what command-line front-ends share (output directories as transactions, progress
# lines, the options that fill the library's Def structs), for a consumer's own tools; not in
# parksim::parksim, since it brings CLI11.
set_target_properties(parksim_cli PROPERTIES EXPORT_NAME cli)
add_library(parksim::cli ALIAS parksim_cli)

list(TRANSFORM parksim_modules PREPEND parksim_ OUTPUT_VARIABLE parksim_module_targets)
install(TARGETS ${parksim_module_targets} parksim_library parksim_cli
  EXPORT parksimTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/parksim/
  DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/parksim
  FILES_MATCHING PATTERN "*.h"
  # Internal to parksim_render: the GL headers, the renderer's state, a film's encoder threads.
  PATTERN "GlFunctions.h" EXCLUDE
  PATTERN "RendererPrograms.h" EXCLUDE
  PATTERN "RendererImpl.h" EXCLUDE
  PATTERN "EncodeQueue.h" EXCLUDE
  # The pages' npm libraries (fetched by scripts/install-deps.sh), built into parksim_pages.
  PATTERN "node_modules" EXCLUDE)
install(EXPORT parksimTargets NAMESPACE parksim:: DESTINATION ${PARKSIM_CMAKE_DIR})

configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/parksimConfig.cmake.in
  ${PROJECT_BINARY_DIR}/parksimConfig.cmake
  INSTALL_DESTINATION ${PARKSIM_CMAKE_DIR})
# 0.x releases break their API between minor versions: 0.3 accepts 0.3.*, not 0.2 or 0.4.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/parksimConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES
  ${PROJECT_BINARY_DIR}/parksimConfig.cmake
  ${PROJECT_BINARY_DIR}/parksimConfigVersion.cmake
  ${PROJECT_SOURCE_DIR}/cmake/parksimImportedTargets.cmake
  ${PROJECT_SOURCE_DIR}/cmake/ParksimPlugin.cmake
  DESTINATION ${PARKSIM_CMAKE_DIR})
