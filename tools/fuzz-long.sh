#!/usr/bin/env bash
# The long fuzz runs of issue 29 item 9: each named harness runs until 10^7 executions or one
# hour of its own CPU time (beside other work a wall-clock hour is less fuzzing), one after the
# other, over its corpus and seeds.
#   tools/fuzz-long.sh WORK_DIR TARGET...      e.g. tools/fuzz-long.sh /tmp/fuzzlong ply pbrt
# Needs build/fuzz (tests/fuzz/README.md). Copies each harness to WORK_DIR/bin first, so that
# rebuilding build/fuzz does not change a running harness. Writes WORK_DIR/logs/TARGET.log
# (libFuzzer's output, its final stats at the end), WORK_DIR/logs/runs.txt (start, end, exit
# status, CPU seconds) and any finding to WORK_DIR/artifacts/. Run two at once on two cores.
# The harnesses write every input to a scratch file under $TMPDIR (tests/fuzz/fuzz_input_file.h):
# kept in memory (/dev/shm) unless TMPDIR is set, since on disk the writes left the cores
# waiting on I/O a third of the time.
set -uo pipefail
[ $# -ge 2 ] || { echo "usage: tools/fuzz-long.sh WORK_DIR TARGET..." >&2; exit 2; }
root=$(cd "$(dirname "$0")/.." && pwd)
work=$1
shift
mkdir -p "$work"/{bin,logs,artifacts,corpus}
tck=$(getconf CLK_TCK)
[ -n "${TMPDIR:-}" ] || { [ -w /dev/shm ] && export TMPDIR=/dev/shm; }
for t in "$@"; do
  src="$root/build/fuzz/tests/fuzz/fuzz_$t"
  [ -x "$src" ] || { echo "tools/fuzz-long.sh: $src was not built" >&2; exit 1; }
  cp "$src" "$work/bin/"
  mkdir -p "$work/corpus/$t"
  echo "start $t $(date -u +%FT%TZ)" >> "$work/logs/runs.txt"
  "$work/bin/fuzz_$t" -seed=29 -runs=10000000 -timeout=20 -rss_limit_mb=2048 -print_final_stats=1 \
    -error_exitcode=1 -timeout_exitcode=1 -artifact_prefix="$work/artifacts/$t-" \
    "$work/corpus/$t" "$root/build/fuzz/tests/fuzz/seeds/$t" > "$work/logs/$t.log" 2>&1 &
  pid=$! cpu=0
  while kill -0 $pid 2>/dev/null; do
    sleep 10
    now=$(awk -v t="$tck" '{print int(($14 + $15) / t)}' /proc/$pid/stat 2>/dev/null) && cpu=$now
    if [ "$cpu" -ge 3600 ]; then kill -INT $pid; fi
  done
  wait $pid
  echo "end $t rc=$? cpu=${cpu}s $(date -u +%FT%TZ)" >> "$work/logs/runs.txt"
  rm -rf "${TMPDIR:-/tmp}/pdrt-fuzz-$pid"  # left behind when SIGINT ends the run
done
