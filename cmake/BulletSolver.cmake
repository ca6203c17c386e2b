# Which multibody solver parksim_sim compiles. parksim's transcription of Bullet's solver
# (parksim/sim/bullet/, its README.md) reads Bullet's internals as Bullet 3.24 has them, so it is
# compiled only against Bullet 3.24 (BT_BULLET_VERSION in LinearMath/btScalar.h, read here) and
# while PARKSIM_BULLET_FAST_SOLVER is ON. Otherwise every solver kernel runs Bullet's own
# btMultiBodyConstraintSolver (the same model, slower; docs/simulation.md), and configuring says
# so in one line. Sets PARKSIM_BULLET_VERSION (e.g. 324, or "unknown") and
# PARKSIM_BULLET_TRANSCRIPTION (ON or OFF).
set(parksim_bullet_transcribed 324)
set(PARKSIM_BULLET_VERSION "unknown")
foreach(dir IN LISTS BULLET_INCLUDE_DIRS)
  if(EXISTS "${dir}/LinearMath/btScalar.h")
    file(STRINGS "${dir}/LinearMath/btScalar.h" parksim_bullet_line
         REGEX "^#define[ \t]+BT_BULLET_VERSION[ \t]+[0-9]+")
    if(parksim_bullet_line)
      string(REGEX REPLACE "^#define[ \t]+BT_BULLET_VERSION[ \t]+([0-9]+).*" "\\1"
             PARKSIM_BULLET_VERSION "${parksim_bullet_line}")
      break()
    endif()
  endif()
endforeach()

if(NOT PARKSIM_BULLET_FAST_SOLVER)
  set(PARKSIM_BULLET_TRANSCRIPTION OFF)
  message(STATUS "Bullet ${PARKSIM_BULLET_VERSION}: Bullet's own multibody solver "
                 "(PARKSIM_BULLET_FAST_SOLVER=OFF)")
elseif(NOT PARKSIM_BULLET_VERSION STREQUAL parksim_bullet_transcribed)
  set(PARKSIM_BULLET_TRANSCRIPTION OFF)
  message(WARNING "Bullet ${PARKSIM_BULLET_VERSION} is not 3.24: parksim uses Bullet's own "
                  "multibody solver, not its faster transcription of 3.24's "
                  "(parksim/sim/bullet/README.md)")
else()
  set(PARKSIM_BULLET_TRANSCRIPTION ON)
endif()
