# The check the test workflow (`cmake --workflow --preset test`) adds after the Release tests, as
# tests of the Release tree that build and run another preset of the same source:
#
#   ci-sanitizers: the sanitize preset (clang, AddressSanitizer + UndefinedBehaviorSanitizer, the
#                  fuzzers' coverage) is built once and its test preset run: the whole test suite
#                  under the sanitizers, then every fuzz target from its seeds for
#                  FOSSSIM_FUZZ_SECONDS seconds.
#
#   ci-web:        the web preset (Emscripten's em++, docs/web.md) is configured, built and its
#                  test preset run: the wasm build's same-bytes checks under Node and the page's
#                  tests in headless Chromium, which compare with this tree's native FOSSSim.
#                  The test workflow runs it last (`ctest --preset ci-web`); its cost on the CI
#                  machine is in docs/web.md, "In CI".
#
# One sanitize build serves both its parts: the tests and the fuzz targets link the same instrumented libraries
# (before, a gcc sanitizer build and a clang fuzz build compiled every library twice;
# docs/limits-and-failures.md has the figures). A workflow preset configures one preset only, so
# the other is configured, built and tested from here. The release test preset leaves this label
# out (ctest --preset release stays the suite of this tree); `ctest --preset ci-sanitizers` runs it.

set(preset_script ${CMAKE_CURRENT_LIST_DIR}/run_preset.cmake)
add_test(NAME ci_sanitizers_build
  COMMAND ${CMAKE_COMMAND} -D PRESET=sanitize -D STEP=build -P ${preset_script}
  WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
add_test(NAME ci_sanitizers_test
  COMMAND ${CMAKE_COMMAND} -D PRESET=sanitize -D STEP=test -P ${preset_script}
  WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
set_tests_properties(ci_sanitizers_build PROPERTIES
  LABELS ci-sanitizers FIXTURES_SETUP ci_sanitizers TIMEOUT 3600)
set_tests_properties(ci_sanitizers_test PROPERTIES
  LABELS ci-sanitizers FIXTURES_REQUIRED ci_sanitizers TIMEOUT 3600)

add_test(NAME ci_web_build
  COMMAND ${CMAKE_COMMAND} -D PRESET=web -D STEP=build -P ${preset_script}
  WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
add_test(NAME ci_web_test
  COMMAND ${CMAKE_COMMAND} -D PRESET=web -D STEP=test -P ${preset_script}
  WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
set_tests_properties(ci_web_build PROPERTIES
  LABELS ci-web FIXTURES_SETUP ci_web TIMEOUT 3600)
set_tests_properties(ci_web_test PROPERTIES
  LABELS ci-web FIXTURES_REQUIRED ci_web TIMEOUT 3600)
