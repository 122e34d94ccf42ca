# The fuzzers in the main build's ctest (included by tests/CMakeLists.txt). fuzz.build configures
# and builds them with clang in their own tree, build/fuzz (every object there is instrumented,
# so it cannot share the GCC build's), once, as the fixture of fuzz.<name>, which runs each for
# PDRT_FUZZ_SECONDS over its seeds and what earlier runs kept (build/fuzz/corpus/<name>).
# Without clang or its libFuzzer runtime both exit 77 and ctest reports them skipped.
include(${CMAKE_CURRENT_LIST_DIR}/fuzz_targets.cmake)
set(PDRT_FUZZ_SECONDS 20 CACHE STRING "Seconds each fuzzer runs under ctest")
set(PDRT_FUZZ_BUILD_DIR ${PROJECT_BINARY_DIR}/fuzz)
add_test(NAME fuzz.build COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/build_fuzzers.sh ${PROJECT_SOURCE_DIR} ${PDRT_FUZZ_BUILD_DIR})
# It compiles with two jobs: ctest gives it two slots.
set_tests_properties(fuzz.build PROPERTIES FIXTURES_SETUP pdrt_fuzzers SKIP_RETURN_CODE 77 PROCESSORS 2 TIMEOUT 1800)
foreach(t ${PDRT_FUZZ_TARGETS})
  add_test(NAME fuzz.${t} COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/run_fuzzer.sh ${PDRT_FUZZ_BUILD_DIR} ${t} ${PDRT_FUZZ_SECONDS})
  set_tests_properties(fuzz.${t} PROPERTIES FIXTURES_REQUIRED pdrt_fuzzers SKIP_RETURN_CODE 77 TIMEOUT 300)
endforeach()
