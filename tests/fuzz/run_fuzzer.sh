#!/usr/bin/env bash
# Runs one fuzzer for a bounded time over its seeds and the corpus earlier runs kept (ctest's
# fuzz.<name>):  run_fuzzer.sh BUILD_DIR NAME SECONDS
# Fails on any crash, hang (> 20 s on one input), leak, out-of-memory (> 2 GiB) or undefined
# behaviour, leaving the input in BUILD_DIR/artifacts/ (libFuzzer prints its path). Exits 77
# (skipped) when fuzz.build did not build the fuzzers.
set -euo pipefail
build=$1 name=$2 seconds=$3
bin="$build/tests/fuzz/fuzz_$name"
if [ ! -x "$bin" ]; then
  echo "fuzz.$name: skipped: $bin was not built (fuzz.build needs clang)"
  exit 77
fi
corpus="$build/corpus/$name"
mkdir -p "$corpus" "$build/artifacts"
# A fixed seed: a run repeats (for the same corpus) instead of depending on the clock. Findings
# exit 1: libFuzzer's own default, 77, is the code ctest reads as skipped.
exec "$bin" -seed=1 -error_exitcode=1 -timeout_exitcode=1 -max_total_time="$seconds" -timeout=20 -rss_limit_mb=2048 -print_final_stats=1 \
  -artifact_prefix="$build/artifacts/$name-" "$corpus" "$build/tests/fuzz/seeds/$name"
