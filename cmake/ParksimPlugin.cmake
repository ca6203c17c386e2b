# parksim_add_plugin(<target> SOURCES <file>...): a plugin (a shared library parksim loads with
# --plugin, parksim/usercode/PluginApi.h) built against parksim::plugin, the plugin API's target:
#
#   find_package(parksim REQUIRED)
#   parksim_add_plugin(my_planners SOURCES my_planner.cpp my_controller.cpp)
#
# makes lib<target>.so. Only the entry point PARKSIM_PLUGIN defines is exported; everything
# else stays hidden, so two plugins never clash over a name.
function(parksim_add_plugin name)
  cmake_parse_arguments(ARG "" "" "SOURCES" ${ARGN})
  if(NOT ARG_SOURCES)
    message(FATAL_ERROR "parksim_add_plugin(${name}): no SOURCES")
  endif()
  add_library(${name} MODULE ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE parksim::plugin)
  target_compile_features(${name} PRIVATE cxx_std_20)
  set_target_properties(${name} PROPERTIES
    PREFIX "lib"
    CXX_VISIBILITY_PRESET hidden
    VISIBILITY_INLINES_HIDDEN ON)
endfunction()
