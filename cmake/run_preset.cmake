# cmake -D PRESET=name -D STEP=build|test -P run_preset.cmake, from the source folder:
# STEP=build configures and builds the preset, STEP=test runs its test preset. Fails when a
# command does. Used by cmake/ci_checks.cmake.

function(run)
  string(REPLACE ";" " " shown "${ARGN}")
  message(STATUS "ci: ${shown}")
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "ci: `${shown}` failed (status ${status})")
  endif()
endfunction()

if(STEP STREQUAL "build")
  run(${CMAKE_COMMAND} --preset ${PRESET})
  run(${CMAKE_COMMAND} --build --preset ${PRESET})
elseif(STEP STREQUAL "test")
  run(${CMAKE_CTEST_COMMAND} --preset ${PRESET})
else()
  message(FATAL_ERROR "run_preset.cmake: STEP must be build or test, found '${STEP}'")
endif()
