# Runs one fuzz target for SECONDS from its committed corpus CORPUS (read only: new inputs go to
# WORK/corpus), with DICTIONARY if it exists; crashes go to WORK/artifacts. Fails when the
# fuzzer finds anything.
file(MAKE_DIRECTORY ${WORK}/corpus ${WORK}/artifacts)
set(arguments -max_total_time=${SECONDS} -timeout=25 -rss_limit_mb=2048 -print_final_stats=1
    -artifact_prefix=${WORK}/artifacts/)
if(EXISTS ${DICTIONARY})
  list(APPEND arguments -dict=${DICTIONARY})
endif()
execute_process(COMMAND ${FUZZER} ${arguments} ${WORK}/corpus ${CORPUS}
                RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${FUZZER} found a failure (status ${status}); its input is in "
                      "${WORK}/artifacts/")
endif()
