# Runs one scene headless and fails unless it reaches its end with the total energy bounded.
#
#   cmake -DFOSSSIM=<FOSSSim executable> -DSCENE=<scene.xml> -DWORK_DIR=<scratch directory>
#         -DSTEPS=<n> -DMAX_ENERGY=<joules> -P run_energy_bounded.cmake
#
# Checks: the run exits 0 and writes --stats-json; it took all n steps; the largest total energy
# of the run (kinetic + potential, over every step) is at most MAX_ENERGY. WORK_DIR is created
# empty and removed afterwards.

foreach(variable FOSSSIM SCENE WORK_DIR STEPS MAX_ENERGY)
  if(NOT DEFINED ${variable})
    message(FATAL_ERROR "run_energy_bounded.cmake: -D${variable}=... is required")
  endif()
endforeach()

file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")
set(stats "${WORK_DIR}/stats.json")

function(fail problem)
  file(REMOVE_RECURSE "${WORK_DIR}")
  message(FATAL_ERROR "${SCENE}: ${problem}\n${ARGN}")
endfunction()

execute_process(
  COMMAND "${FOSSSIM}" -s "${SCENE}" -d 0 -q --stats-json "${stats}"
  RESULT_VARIABLE status OUTPUT_VARIABLE run_out ERROR_VARIABLE run_err)
if(NOT status EQUAL 0)
  fail("the run exited with status ${status}" "${run_out}${run_err}")
endif()
if(NOT EXISTS "${stats}")
  fail("the run wrote no --stats-json" "${run_out}${run_err}")
endif()
file(READ "${stats}" json)
string(JSON steps GET "${json}" steps)
string(JSON initial GET "${json}" energy initial)
string(JSON largest GET "${json}" energy max)
string(JSON final GET "${json}" energy final)
message(STATUS "${steps} steps; energy initial ${initial}, max ${largest}, final ${final}")
if(NOT steps EQUAL STEPS)
  fail("the run took ${steps} steps, not ${STEPS}")
endif()
# if(… GREATER …) compares the numbers as doubles.
if(largest GREATER MAX_ENERGY OR NOT largest GREATER -1e300)
  fail("the total energy reached ${largest} J, above the bound ${MAX_ENERGY} J (initial ${initial} J)")
endif()
file(REMOVE_RECURSE "${WORK_DIR}")
