# Fails when a source file includes a FOSSSim header ("folder/name.h") from a folder whose
# library (fosssim_<folder>) its target does not link. Run by the build (fosssim_check_includes
# in cmake/layering.cmake):
#   cmake -D FILES=a.cpp|b.h -D FOLDERS=core|io -D STAMP=file -P check_includes.cmake
# Lists are separated by "|". Includes without a folder (the target's own headers) and <...>
# includes are not checked. On success STAMP is touched.

cmake_minimum_required(VERSION 3.25)

string(REPLACE "|" ";" FILES "${FILES}")
string(REPLACE "|" ";" FOLDERS "${FOLDERS}")
set(problems "")
foreach(source IN LISTS FILES)
  file(READ "${source}" content)
  string(REGEX MATCHALL "#[ \t]*include[ \t]*\"[^\"/]+/[^\"]*\"" includes "${content}")
  foreach(include IN LISTS includes)
    string(REGEX REPLACE "^#[ \t]*include[ \t]*\"([^\"/]+)/.*$" "\\1" folder "${include}")
    if(NOT folder IN_LIST FOLDERS)
      string(FIND "${content}" "${include}" offset)
      string(SUBSTRING "${content}" 0 ${offset} before)
      string(REGEX MATCHALL "\n" newlines "${before}")
      list(LENGTH newlines line)
      math(EXPR line "${line} + 1")
      string(APPEND problems "\n  ${source}:${line}: ${include}: the target does not link "
                             "fosssim_${folder}")
    endif()
  endforeach()
endforeach()
if(problems)
  message(FATAL_ERROR "Headers from libraries that are not linked:${problems}\n"
                      "Link the library (fosssim_<folder>), or do not include the header.")
endif()
file(TOUCH "${STAMP}")
