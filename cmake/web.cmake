# The WebAssembly build's dependencies and flags (FOSSSIM_WEB; docs/web.md). Included by the
# top-level CMakeLists.txt instead of the native find_package calls.
#
# Everything the web build uses from Debian is header-only: Eigen, nlohmann_json, rapidxml and
# fast_float. em++ must not see the rest of /usr/include (glibc's headers would shadow
# Emscripten's own C library), so each header folder is linked into one include folder of the
# build tree, and the usual target names point there.

set(FOSSSIM_WEB_INCLUDE_DIR ${PROJECT_BINARY_DIR}/web-include)
file(MAKE_DIRECTORY ${FOSSSIM_WEB_INCLUDE_DIR})
foreach(header IN ITEMS Eigen/Core nlohmann/json.hpp rapidxml/rapidxml.hpp fast_float/fast_float.h)
  get_filename_component(folder ${header} DIRECTORY)
  string(MAKE_C_IDENTIFIER ${folder} id)
  find_path(FOSSSIM_WEB_${id}_DIR ${header} PATHS /usr/include PATH_SUFFIXES eigen3
            NO_CMAKE_FIND_ROOT_PATH REQUIRED)
  if(NOT EXISTS ${FOSSSIM_WEB_INCLUDE_DIR}/${folder})
    file(CREATE_LINK ${FOSSSIM_WEB_${id}_DIR}/${folder} ${FOSSSIM_WEB_INCLUDE_DIR}/${folder} SYMBOLIC)
  endif()
endforeach()

add_library(Eigen3::Eigen INTERFACE IMPORTED)
set_target_properties(Eigen3::Eigen PROPERTIES INTERFACE_INCLUDE_DIRECTORIES ${FOSSSIM_WEB_INCLUDE_DIR})
add_library(nlohmann_json::nlohmann_json INTERFACE IMPORTED)
set_target_properties(nlohmann_json::nlohmann_json PROPERTIES
                      INTERFACE_INCLUDE_DIRECTORIES ${FOSSSIM_WEB_INCLUDE_DIR})
set(FOSSSIM_RAPIDXML_INCLUDE_DIR ${FOSSSIM_WEB_INCLUDE_DIR})
set(FOSSSIM_FAST_FLOAT_INCLUDE_DIR ${FOSSSIM_WEB_INCLUDE_DIR})

# Scene errors are exceptions: WebAssembly's own exception handling (Node and Chromium have it),
# which costs nothing until something is thrown; Emscripten's default would abort instead.
add_compile_options(-fwasm-exceptions)
add_link_options(-fwasm-exceptions -sALLOW_MEMORY_GROWTH=1)
# The link optimizes the wasm (wasm-opt) only when told to, as the objects were compiled.
add_link_options($<$<CONFIG:Release>:-O3>)

# The same bytes as the native build: -ffp-contract=off is set for every build above (and
# WebAssembly has no fused multiply-add to contract into), and Eigen must sum in the same order.
# Natively it runs its SSE2 kernels (x86-64's baseline), whose reductions add in pairs of
# lanes; its scalar code would add in another order. Emscripten translates SSE2 intrinsics to
# WebAssembly SIMD (-msimd128 -msse2), so Eigen runs the same kernels here, with three
# adjustments to Eigen 3.4's SSE code, none of which changes a result: an empty mmintrin.h
# (Emscripten has no MMX; Eigen includes it but uses nothing from it); clang presenting itself
# as GCC 7 (-fgnuc-version=7) rather than GCC 4.2, so that Eigen skips the x86 assembly it uses
# to work around a bug of GCC before 6.3; and its remaining empty asm statements (register
# allocation hints for x86 in the matrix product kernel) defined away.
add_compile_options(-msimd128 -msse2 -fgnuc-version=7 "-D__asm__(...)=")
# file(CONFIGURE) writes it only when its text changes: a new timestamp at every configure made
# every object that includes Eigen out of date, so each re-configure rebuilt the whole tree.
file(CONFIGURE OUTPUT ${FOSSSIM_WEB_INCLUDE_DIR}/mmintrin.h
     CONTENT "/* Emscripten has no MMX; Eigen includes this header but uses only SSE2 (cmake/web.cmake). */\n")

# Node runs the wasm programs of the tests (web/): Debian's Node modules for em++ itself, and
# the program's JavaScript and wasm in one file, which recent Node loads without fetch().
find_program(FOSSSIM_NODE node REQUIRED NO_CMAKE_FIND_ROOT_PATH)
