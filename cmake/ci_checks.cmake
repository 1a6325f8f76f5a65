# The checks the test workflow (`cmake --workflow --preset test`) adds after the Release tests,
# as tests of the Release tree that build and run other presets of the same source:
#
#   ci-sanitizers: the debug preset (AddressSanitizer + UndefinedBehaviorSanitizer) is built and
#                  its whole test suite run;
#   ci-fuzz:       the fuzz preset (clang, libFuzzer) is built and every target runs from its
#                  seeds for FOSSSIM_FUZZ_SECONDS seconds (ctest --preset fuzz).
#
# A workflow preset configures one preset only, so the others are configured, built and tested
# from here. The release test preset leaves these labels out (ctest --preset release stays the
# suite of this tree); `ctest --preset ci-sanitizers` and `ctest --preset ci-fuzz` run them.

set(preset_script ${CMAKE_CURRENT_LIST_DIR}/run_preset.cmake)
foreach(check IN ITEMS sanitizers fuzz)
  set(preset ${check})
  if(check STREQUAL "sanitizers")
    set(preset debug)
  endif()
  add_test(NAME ci_${check}_build
    COMMAND ${CMAKE_COMMAND} -D PRESET=${preset} -D STEP=build -P ${preset_script}
    WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
  add_test(NAME ci_${check}_test
    COMMAND ${CMAKE_COMMAND} -D PRESET=${preset} -D STEP=test -P ${preset_script}
    WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
  set_tests_properties(ci_${check}_build PROPERTIES
    LABELS ci-${check} FIXTURES_SETUP ci_${check} TIMEOUT 3600)
  set_tests_properties(ci_${check}_test PROPERTIES
    LABELS ci-${check} FIXTURES_REQUIRED ci_${check} TIMEOUT 3600)
endforeach()
