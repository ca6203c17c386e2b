# Targets for the dependencies that have no imported target of their own. Included by the
# project and by the installed parksimConfig.cmake, so both define them the same way; static
# parksim libraries name them in their link interface.

# Float Bullet only: float headers with the -float64 libraries link but return garbage.
# FindBullet (CMake's own module) gives absolute paths; Bullet's config file does not.
if(NOT TARGET parksim::bullet)
  add_library(parksim::bullet INTERFACE IMPORTED)
  set_target_properties(parksim::bullet PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES "${BULLET_INCLUDE_DIRS}"
    INTERFACE_SYSTEM_INCLUDE_DIRECTORIES "${BULLET_INCLUDE_DIRS}"
    INTERFACE_LINK_LIBRARIES "${BULLET_LIBRARIES}")
endif()

# Debian's libstb contains the implementations of stb_image and stb_truetype.
if(NOT TARGET parksim::stb)
  add_library(parksim::stb UNKNOWN IMPORTED)
  set_target_properties(parksim::stb PROPERTIES IMPORTED_LOCATION "${PARKSIM_STB_LIBRARY}")
endif()
