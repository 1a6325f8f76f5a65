# One benchmark's smoke test (cmake -P): runs BENCH with ARGS (its quickest options, a
# space-separated list) and passes when it exits 0 and its output holds a line matching HEADER
# (the table's header) followed, on a later line, by one matching ROW (a row of numbers), and no
# line matching FORBID when that is set (a check the benchmark prints, such as "RECORDS DIFFER").
# It asserts nothing about speed: it only shows that the benchmark still builds, runs and prints
# its table. The patterns are CMake regular expressions matched against one line at a time.

separate_arguments(arguments UNIX_COMMAND "${ARGS}")
execute_process(COMMAND "${BENCH}" ${arguments} RESULT_VARIABLE status OUTPUT_VARIABLE output
                ERROR_VARIABLE errors)
message("${output}${errors}")  # what ctest --output-on-failure shows
if(NOT status STREQUAL "0")
  message(FATAL_ERROR "${BENCH} ${ARGS} ended with ${status}")
endif()

# Lines as list elements: ';' would split a line, and '[' ']' keep CMake from splitting at all.
string(REPLACE ";" "," output "${output}")
string(REPLACE "[" "(" output "${output}")
string(REPLACE "]" ")" output "${output}")
string(REPLACE "\n" ";" lines "${output}")
set(seen_header FALSE)
set(seen_row FALSE)
foreach(line IN LISTS lines)
  if(DEFINED FORBID AND line MATCHES "${FORBID}")
    message(FATAL_ERROR "${BENCH} printed '${line}'")
  endif()
  if(seen_header AND line MATCHES "${ROW}")
    set(seen_row TRUE)
  elseif(NOT seen_header AND line MATCHES "${HEADER}")
    set(seen_header TRUE)
  endif()
endforeach()
if(NOT seen_header)
  message(FATAL_ERROR "${BENCH} printed no line matching the header '${HEADER}'")
endif()
if(NOT seen_row)
  message(FATAL_ERROR "${BENCH} printed no row matching '${ROW}' after its header")
endif()
