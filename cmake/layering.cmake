# The layering of FOSSSim's libraries, checked by the build (docs/architecture.md, 'Layering').
#
# Every library lives in one folder (FOSSSim/core, FOSSSim/io, ...; the oracle in oracle/src)
# and its headers are included as "folder/name.h". fosssim_check_includes(target FOLDER name
# DIR dir) makes the build of `target` fail when one of its files includes a header from a
# folder that is neither its own nor the folder of a library it links directly, so that what a
# target includes and what it links cannot drift apart: core cannot include io, the oracle
# cannot include app. Its files are its .cpp sources, the headers beside them, and, for the
# folder's main target (PRIMARY), every other header of the folder that does not belong to
# another target's source. Call it after target_link_libraries.

# Where each library's headers live, by library target.
set(FOSSSIM_LIBRARY_FOLDERS
  fosssim_core=core fosssim_mesh=mesh fosssim_io=io fosssim_grading=grading
  fosssim_scripting=scripting fosssim_render=render fosssim_pictures=pictures
  fosssim_viewer_logic=viewer fosssim_viewer=viewer fosssim_cli=cli fosssim_oracle=oracle
  fosssim_outputs=outputs)

function(fosssim_check_includes target)
  cmake_parse_arguments(PARSE_ARGV 1 arg "PRIMARY" "FOLDER;DIR" "")
  set(folders ${arg_FOLDER})
  get_target_property(links ${target} LINK_LIBRARIES)
  foreach(library IN LISTS links)
    foreach(entry IN LISTS FOSSSIM_LIBRARY_FOLDERS)
      if(entry MATCHES "^${library}=(.+)$")
        list(APPEND folders ${CMAKE_MATCH_1})
      endif()
    endforeach()
  endforeach()
  list(REMOVE_DUPLICATES folders)

  # The target's files: its sources under DIR, the headers beside them, and for the main target
  # the folder's other headers that belong to no other target's source.
  get_target_property(sources ${target} SOURCES)
  get_target_property(source_dir ${target} SOURCE_DIR)
  set(files "")
  set(own_stems "")
  foreach(source IN LISTS sources)
    cmake_path(ABSOLUTE_PATH source BASE_DIRECTORY ${source_dir} OUTPUT_VARIABLE source)
    if(source MATCHES "\\.cpp$" AND source MATCHES "^${arg_DIR}/")
      list(APPEND files ${source})
      string(REGEX REPLACE "\\.cpp$" "" stem "${source}")
      list(APPEND own_stems ${stem})
      if(EXISTS ${stem}.h)
        list(APPEND files ${stem}.h)
      endif()
    endif()
  endforeach()
  if(arg_PRIMARY)
    file(GLOB_RECURSE headers CONFIGURE_DEPENDS ${arg_DIR}/*.h)
    file(GLOB_RECURSE all_sources CONFIGURE_DEPENDS ${arg_DIR}/*.cpp)
    foreach(header IN LISTS headers)
      string(REGEX REPLACE "\\.h$" "" stem "${header}")
      if(stem IN_LIST own_stems OR NOT EXISTS ${stem}.cpp)
        list(APPEND files ${header})
      endif()
    endforeach()
  endif()
  list(REMOVE_DUPLICATES files)

  string(REPLACE ";" "|" files_arg "${files}")
  string(REPLACE ";" "|" folders_arg "${folders}")
  set(stamp ${CMAKE_CURRENT_BINARY_DIR}/${target}.includes-checked)
  add_custom_command(OUTPUT ${stamp}
    COMMAND ${CMAKE_COMMAND} -DFILES=${files_arg} -DFOLDERS=${folders_arg} -DSTAMP=${stamp}
            -P ${PROJECT_SOURCE_DIR}/cmake/check_includes.cmake
    DEPENDS ${files} ${PROJECT_SOURCE_DIR}/cmake/check_includes.cmake
    COMMENT "Checking that ${target} includes only headers of the libraries it links"
    VERBATIM)
  target_sources(${target} PRIVATE ${stamp})
endfunction()
