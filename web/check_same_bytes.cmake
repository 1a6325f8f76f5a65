# One scene's trajectory from the WebAssembly build (fosssim-web-run under Node) must have the
# same SHA-256 as the native build's: the regression manifest's entry (-DMANIFEST=golden.tsv), or
# the native program's own run (-DNATIVE=FOSSSim; ctest reports "skipped" when there is none);
# with -DSIZE_ONLY=ON only its size (scenes that call libm's sin, cos or atan2, rigid contact
# without ODE; docs/web.md), and then, when -DGRADER names a native FOSSSim that exists, that
# the native grader (-i, the course's criteria: every step retaken from the file's previous
# state) passes it: the same physics to round-off.
#   cmake -DNODE=node -DDRIVER=fosssim-web-run.js -DSOURCE_DIR=... -DSCENE=assets/... \
#         -DWORK_DIR=... (-DMANIFEST=... | -DNATIVE=...) -P check_same_bytes.cmake

string(MAKE_C_IDENTIFIER ${SCENE} name)
file(MAKE_DIRECTORY ${WORK_DIR})
set(web_output ${WORK_DIR}/${name}.web.bin)
file(REMOVE ${web_output})
string(TIMESTAMP start "%s")
execute_process(COMMAND ${NODE} ${DRIVER} ${SOURCE_DIR}/${SCENE} ${web_output}
                WORKING_DIRECTORY ${SOURCE_DIR} RESULT_VARIABLE status OUTPUT_QUIET
                ERROR_VARIABLE errors)
string(TIMESTAMP end "%s")
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${SCENE}: the wasm run failed (exit ${status}):\n${errors}")
endif()
file(SHA256 ${web_output} web_digest)
file(SIZE ${web_output} web_bytes)

if(DEFINED MANIFEST)
  file(STRINGS ${MANIFEST} entries REGEX "^${SCENE}\t")
  list(LENGTH entries count)
  if(NOT count EQUAL 1)
    message(FATAL_ERROR "${SCENE}: ${count} entries in ${MANIFEST}, expected one")
  endif()
  string(REPLACE "\t" ";" fields "${entries}")
  list(GET fields 3 native_bytes)
  list(GET fields 4 native_digest)
  set(reference "the manifest ${MANIFEST}")
else()
  if(NOT EXISTS ${NATIVE})
    message(STATUS "${SCENE}: no native FOSSSim at ${NATIVE} to compare with; skipped")
    return()
  endif()
  set(native_output ${WORK_DIR}/${name}.native.bin)
  file(REMOVE ${native_output})
  execute_process(COMMAND ${NATIVE} -s ${SOURCE_DIR}/${SCENE} -d 0 -o ${native_output}
                  RESULT_VARIABLE status OUTPUT_QUIET ERROR_VARIABLE errors)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${SCENE}: the native run failed (exit ${status}):\n${errors}")
  endif()
  file(SHA256 ${native_output} native_digest)
  file(SIZE ${native_output} native_bytes)
  set(reference "the native run of ${NATIVE}")
endif()

math(EXPR seconds "${end} - ${start}")
if(SIZE_ONLY)  # -DSIZE_ONLY=ON: the native size (frames and layout) is all that is expected
  if(NOT web_bytes EQUAL native_bytes)
    message(FATAL_ERROR "${SCENE}: the wasm trajectory has ${web_bytes} bytes, ${reference} "
                        "${native_bytes}; it is kept in ${web_output}")
  endif()
  set(graded "")
  if(DEFINED GRADER AND EXISTS ${GRADER})
    execute_process(COMMAND ${GRADER} -s ${SOURCE_DIR}/${SCENE} -d 0 -q -i ${web_output}
                    RESULT_VARIABLE status OUTPUT_VARIABLE report ERROR_VARIABLE errors)
    if(NOT status EQUAL 0)
      message(FATAL_ERROR "${SCENE}: the native grader ${GRADER} fails the wasm trajectory "
                          "(exit ${status}):\n${report}${errors}")
    endif()
    set(graded "; the native grader passes it")
  endif()
  message(STATUS "${SCENE}: the size of ${reference} (${web_bytes} bytes; wasm run ${seconds} s)"
                 "${graded}")
  return()
endif()
if(NOT web_digest STREQUAL native_digest OR NOT web_bytes EQUAL native_bytes)
  message(FATAL_ERROR "${SCENE}: the wasm trajectory differs from ${reference}: sha256 "
                      "${web_digest} (${web_bytes} bytes) against ${native_digest} "
                      "(${native_bytes} bytes); it is kept in ${web_output}")
endif()
message(STATUS "${SCENE}: same bytes as ${reference} (${web_bytes} bytes, sha256 "
               "${web_digest}; wasm run ${seconds} s)")
