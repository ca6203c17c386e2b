# Run at build time (cmake -P) by the parksim_git_commit target: writes OUT (a header) with the
# commit of SOURCE_DIR and whether tracked files differ from it. configure_file rewrites OUT only
# when its text changes, so an unchanged tree recompiles nothing.
#   -DSOURCE_DIR=... -DOUT=... -DTEMPLATE=...
set(PARKSIM_GIT_COMMIT "unknown")
set(PARKSIM_GIT_DIRTY "false")
find_package(Git QUIET)
if(GIT_FOUND)
  execute_process(COMMAND "${GIT_EXECUTABLE}" rev-parse HEAD
                  WORKING_DIRECTORY "${SOURCE_DIR}" RESULT_VARIABLE rc
                  OUTPUT_VARIABLE commit ERROR_QUIET OUTPUT_STRIP_TRAILING_WHITESPACE)
  if(rc EQUAL 0 AND commit MATCHES "^[0-9a-f]+$")
    set(PARKSIM_GIT_COMMIT "${commit}")
    # Untracked files do not change the build's sources unless CMake lists them; tracked ones do.
    execute_process(COMMAND "${GIT_EXECUTABLE}" status --porcelain --untracked-files=no
                    WORKING_DIRECTORY "${SOURCE_DIR}" RESULT_VARIABLE rc
                    OUTPUT_VARIABLE status ERROR_QUIET OUTPUT_STRIP_TRAILING_WHITESPACE)
    if(NOT rc EQUAL 0 OR NOT status STREQUAL "")
      set(PARKSIM_GIT_DIRTY "true")
    endif()
  endif()
endif()
configure_file("${TEMPLATE}" "${OUT}" @ONLY)
