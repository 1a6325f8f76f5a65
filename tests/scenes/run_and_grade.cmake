# Runs one scene headless and grades its trajectory with FOSSSim's own grading mode, exactly as the
# course's grading script does, and fails unless both succeed.
#
#   cmake -DFOSSSIM=<FOSSSim executable> -DSCENE=<scene.xml> -DWORK_DIR=<scratch directory>
#         -P run_and_grade.cmake
#
# Checks, in order: the run exits 0, prints nothing on stderr (with -q only warnings and errors go
# there, so the scene loads without warnings) and writes the trajectory; grading exits 0 and prints
# the line "Overall success: Passed.". WORK_DIR is created empty and removed afterwards.

foreach(variable FOSSSIM SCENE WORK_DIR)
  if(NOT DEFINED ${variable})
    message(FATAL_ERROR "run_and_grade.cmake: -D${variable}=... is required")
  endif()
endforeach()

file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")
set(trajectory "${WORK_DIR}/out.bin")

function(fail problem)
  file(REMOVE_RECURSE "${WORK_DIR}")
  message(FATAL_ERROR "${SCENE}: ${problem}\n${ARGN}")
endfunction()

execute_process(
  COMMAND "${FOSSSIM}" -s "${SCENE}" -d 0 -q -o "${trajectory}"
  RESULT_VARIABLE status OUTPUT_VARIABLE run_out ERROR_VARIABLE run_err)
if(NOT status EQUAL 0)
  fail("the run exited with status ${status}" "${run_out}${run_err}")
endif()
if(NOT run_err STREQUAL "")
  fail("the run printed warnings or errors" "${run_err}")
endif()
if(NOT EXISTS "${trajectory}")
  fail("the run wrote no trajectory" "${run_out}")
endif()
file(SIZE "${trajectory}" bytes)

execute_process(
  COMMAND "${FOSSSIM}" -s "${SCENE}" -d 0 -q -i "${trajectory}"
          --residual-file "${WORK_DIR}/residual.txt"
  RESULT_VARIABLE status OUTPUT_VARIABLE grade_out ERROR_VARIABLE grade_err)
if(NOT status EQUAL 0)
  fail("grading exited with status ${status}" "${grade_out}${grade_err}")
endif()
if(NOT grade_out MATCHES "(^|\n)Overall success: Passed\\.\n")
  fail("grading did not print 'Overall success: Passed.'" "${grade_out}${grade_err}")
endif()

file(REMOVE_RECURSE "${WORK_DIR}")
message(STATUS "passed: ${SCENE} (${bytes} bytes of trajectory)")
