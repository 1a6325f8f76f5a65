# Installs a build into a scratch prefix and checks that it is usable from there: the programs
# run, a project of its own finds the package FOSSSim and builds against it, and the Python
# module imports. Run by ctest (install.consumer):
#   cmake -DBUILD_DIR=... -DSOURCE_DIR=... -DWORK_DIR=... -DGENERATOR=Ninja [-DPYTHON=...]
#         [-DLAUNCHER=ccache] -P check_install.cmake

cmake_minimum_required(VERSION 3.25)

function(run)
  execute_process(COMMAND ${ARGV} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    string(REPLACE ";" " " command "${ARGV}")
    message(FATAL_ERROR "failed (${status}): ${command}\n${out}\n${err}")
  endif()
  set(run_output "${out}" PARENT_SCOPE)
endfunction()

file(REMOVE_RECURSE ${WORK_DIR})
set(prefix ${WORK_DIR}/prefix)
run(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})

foreach(file IN ITEMS bin/FOSSSim bin/FOSSSim-generate bin/fosssim-oracle
                      include/fosssim/core/force.h include/fosssim/io/scene_loader.h)
  if(NOT EXISTS ${prefix}/${file})
    message(FATAL_ERROR "the install has no ${file}")
  endif()
endforeach()
file(GLOB config ${prefix}/lib*/cmake/FOSSSim/FOSSSimConfig.cmake
                 ${prefix}/lib/*/cmake/FOSSSim/FOSSSimConfig.cmake)
if(NOT config)
  message(FATAL_ERROR "the install has no lib/.../cmake/FOSSSim/FOSSSimConfig.cmake")
endif()

# The installed program runs a scene.
set(scene ${SOURCE_DIR}/assets/t1m1/springs_spinning_triangle.xml)
run(${prefix}/bin/FOSSSim -s ${scene} -d 0 -o ${WORK_DIR}/installed.bin -q)

# A project of its own, against the installed tree only.
set(launcher "")
if(LAUNCHER)
  set(launcher -DCMAKE_CXX_COMPILER_LAUNCHER=${LAUNCHER})
endif()
run(${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/install/consumer -B ${WORK_DIR}/consumer -G ${GENERATOR}
    -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH=${prefix} ${launcher})
run(${CMAKE_COMMAND} --build ${WORK_DIR}/consumer)
run(${WORK_DIR}/consumer/consumer ${scene} ${WORK_DIR}/last.png)
if(NOT run_output MATCHES "^steps [0-9]+ time [0-9.e+-]+ energy ")
  message(FATAL_ERROR "the consumer printed: ${run_output}")
endif()
if(NOT EXISTS ${WORK_DIR}/last.png)
  message(FATAL_ERROR "the consumer wrote no picture")
endif()
message(STATUS "consumer: ${run_output}")

# The installed Python module imports and runs the same scene.
if(PYTHON)
  file(GLOB_RECURSE module ${prefix}/*.py)
  list(FILTER module INCLUDE REGEX "/fosssim/__init__\\.py$")
  if(NOT module)
    message(FATAL_ERROR "the install has no Python package fosssim")
  endif()
  list(GET module 0 module)
  cmake_path(GET module PARENT_PATH package)
  cmake_path(GET package PARENT_PATH site)
  # Statements separated by newlines: a ';' would split the argument into a CMake list.
  run(${CMAKE_COMMAND} -E env PYTHONPATH=${site} ${PYTHON} -c
      "import fosssim\ns = fosssim.Simulation(fosssim.load_scene('${scene}'))\ns.run()\nprint(s.step_count, fosssim.__file__)")
  if(NOT run_output MATCHES "^4000 ${site}/fosssim/__init__.py")
    message(FATAL_ERROR "the installed module printed: ${run_output}")
  endif()
  message(STATUS "installed module ran ${run_output}")
endif()
file(REMOVE_RECURSE ${WORK_DIR})
