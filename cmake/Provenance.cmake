# Build provenance for parksim_core (parksim/core/system/Provenance.h): what is fixed at
# configure time (version, build type, compiler, Bullet precision) goes into ProvenanceConfig.h;
# the git commit is captured on every build into ProvenanceGit.h, so a rebuilt binary never
# reports the commit it was configured at.
set(PARKSIM_GENERATED_DIR "${PROJECT_BINARY_DIR}/generated")

set(PARKSIM_BUILD_TYPE "${CMAKE_BUILD_TYPE}")
if(PARKSIM_BUILD_TYPE STREQUAL "")
  set(PARKSIM_BUILD_TYPE "unspecified")
endif()
if(PARKSIM_SANITIZE)
  string(APPEND PARKSIM_BUILD_TYPE "+asan+ubsan")
endif()
set(PARKSIM_COMPILER "${CMAKE_CXX_COMPILER_ID} ${CMAKE_CXX_COMPILER_VERSION}")
# Bullet's precision is a compile-time switch of its headers (BT_USE_DOUBLE_PRECISION); parksim
# builds against float Bullet unless that definition is set on parksim_bullet. parksim_sim
# static_asserts that btScalar agrees, so the recorded value cannot drift from the real one.
get_target_property(parksim_bullet_defs parksim_bullet INTERFACE_COMPILE_DEFINITIONS)
if(parksim_bullet_defs MATCHES "BT_USE_DOUBLE_PRECISION")
  set(PARKSIM_BULLET_DOUBLE 1)
  set(PARKSIM_BULLET_PRECISION "double")
else()
  set(PARKSIM_BULLET_DOUBLE 0)
  set(PARKSIM_BULLET_PRECISION "float")
endif()
configure_file("${PROJECT_SOURCE_DIR}/parksim/core/system/ProvenanceConfig.h.in"
               "${PARKSIM_GENERATED_DIR}/parksim/core/system/ProvenanceConfig.h" @ONLY)

add_custom_target(parksim_git_commit
  COMMAND "${CMAKE_COMMAND}" -DSOURCE_DIR=${PROJECT_SOURCE_DIR}
          -DOUT=${PARKSIM_GENERATED_DIR}/parksim/core/system/ProvenanceGit.h
          -DTEMPLATE=${PROJECT_SOURCE_DIR}/parksim/core/system/ProvenanceGit.h.in
          -P "${PROJECT_SOURCE_DIR}/cmake/GitCommit.cmake"
  BYPRODUCTS "${PARKSIM_GENERATED_DIR}/parksim/core/system/ProvenanceGit.h"
  COMMENT "Recording the git commit"
  VERBATIM)
