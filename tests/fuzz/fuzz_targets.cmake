# The fuzzers, one per reader of user files: tests/fuzz/fuzz_<name>.cpp. Read by the fuzz build
# (CMakeLists.txt here) and by the main build's ctest registration (fuzz_tests.cmake).
set(PDRT_FUZZ_TARGETS pbrt ply scene_json obj table point_csv plan)
