#!/usr/bin/env bash
# Configures and builds the fuzzers with clang in their own build tree (ctest's fuzz.build):
#   build_fuzzers.sh SOURCE_DIR BUILD_DIR
# Exits 77 (ctest: skipped) when clang or its libFuzzer runtime is missing; install-deps.sh
# installs both. PDRT_FUZZ_CXX names another clang++.
set -euo pipefail
src=$1 build=$2
cxx=${PDRT_FUZZ_CXX:-clang++}
mkdir -p "$build"
if ! command -v "$cxx" >/dev/null 2>&1; then
  echo "fuzz.build: skipped: $cxx not found (bash third_party/install-deps.sh installs clang)"
  exit 77
fi
probe="$build/libfuzzer-probe"
if ! echo 'extern "C" int LLVMFuzzerTestOneInput(const unsigned char*, unsigned long) { return 0; }' |
    "$cxx" -x c++ -fsanitize=fuzzer,address,undefined - -o "$probe" >"$probe.log" 2>&1; then
  echo "fuzz.build: skipped: $cxx cannot link -fsanitize=fuzzer,address,undefined (Debian: libclang-rt-dev):"
  cat "$probe.log"
  exit 77
fi
launcher=()
if command -v ccache >/dev/null 2>&1; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
log="$build/build.log"
if ! { cmake -S "$src" -B "$build" -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_BUILD_TYPE=Debug -DPDRT_FUZZ=ON \
         -DPDRT_BUILD_TESTS=OFF -DPDRT_BUILD_BENCH=OFF "${launcher[@]}" &&
       cmake --build "$build" --target pdrt_fuzzers -j"${PDRT_FUZZ_JOBS:-2}"; } >"$log" 2>&1; then
  tail -n 40 "$log"
  echo "fuzz.build: failed, the whole log is $log"
  exit 1
fi
echo "fuzz.build: built the fuzzers in $build/tests/fuzz (log: $log)"
