# Packs the build with `cpack -G DEB` and checks the package's file list (dpkg -c): programs,
# headers, libraries, the CMake package and, when built, the Python module. Run by ctest
# (install.deb): cmake -DBUILD_DIR=... -DWORK_DIR=... [-DPYTHON_MODULE=ON] -P check_deb.cmake

cmake_minimum_required(VERSION 3.25)
file(REMOVE_RECURSE ${WORK_DIR})
execute_process(COMMAND cpack --config ${BUILD_DIR}/CPackConfig.cmake -G DEB -B ${WORK_DIR}
                RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "cpack failed:\n${out}\n${err}")
endif()
file(GLOB package ${WORK_DIR}/fosssim_*.deb)
if(NOT package)
  message(FATAL_ERROR "cpack wrote no fosssim_*.deb in ${WORK_DIR}:\n${out}")
endif()
execute_process(COMMAND dpkg -c ${package} RESULT_VARIABLE status OUTPUT_VARIABLE listing)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "dpkg -c ${package} failed")
endif()
set(expected ./usr/bin/FOSSSim ./usr/bin/fosssim-oracle ./usr/include/fosssim/core/force.h
             /cmake/FOSSSim/FOSSSimConfig.cmake /cmake/FOSSSim/FOSSSimTargets.cmake
             /libfosssim_core.a)
if(PYTHON_MODULE)
  list(APPEND expected ./usr/lib/python3/dist-packages/fosssim/__init__.py
                       "./usr/lib/python3/dist-packages/fosssim/_core")
endif()
foreach(path IN LISTS expected)
  string(FIND "${listing}" "${path}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "${package} lacks ${path}; it holds:\n${listing}")
  endif()
endforeach()
file(SIZE ${package} bytes)
message(STATUS "${package}: ${bytes} bytes")
file(REMOVE_RECURSE ${WORK_DIR})
