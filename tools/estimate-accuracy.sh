#!/usr/bin/env bash
# How far the estimate `pdrt render` prints before it starts (renderer/render/render_estimate.h)
# is from the time its passes then take: every scene in scenes/ (*.json, examples/*.json,
# pbrt/*/*.pbrt; SCENES picks others) at 1, 16 and 256 spp, at
# a reduced size (default 128x128) to keep it affordable. One line per render: the estimate and
# the passes' wall seconds, their ratio (actual / estimate; the aim is within [1/1.5, 1.5]), and
# the same ratio in process CPU seconds per sample, which a load that changes during the render
# does not move (the method's own error). PDRT_BUILD picks the build folder (default build).
# Usage: [SPPS="1 16 256"] tools/estimate-accuracy.sh [SIZE] [THREADS]
set -euo pipefail
size=${1:-128}
threads=${2:-0}
B=$(cd "${PDRT_BUILD:-build}" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
printf "%-26s %5s %10s %10s %8s %8s\n" scene spp estimate_s actual_s ratio cpu_ratio
shopt -s nullglob
for scene in ${SCENES:-scenes/*.json scenes/examples/*.json scenes/pbrt/*/*.pbrt}; do
  for spp in ${SPPS:-1 16 256}; do
    "$B/pdrt" render "$scene" --width "$size" --height "$size" --spp "$spp" --threads "$threads" -q \
      -o "$work/o.exr" --stats "$work/s.json"
    python3 - "$work/s.json" "$(basename "${scene%.*}")" "$spp" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
e = j["estimate"]
actual = j["passes_seconds"]
cal_cpu = e["calibration_cpu_seconds"] / e["calibration_samples"]
# The samples the passes took: all of them, less the calibration's when it kept them.
passes = (e["seconds"] - e["loops"] * e["loop_seconds"]) / (1e-9 * e["ns_per_sample"]) if e["ns_per_sample"] > 0 else j["samples"]
pass_cpu = (j["cpu_seconds"] - e["calibration_cpu_seconds"]) / max(passes, 1)
print("%-26s %5s %10.4f %10.4f %8.2f %8.2f" % (sys.argv[2], sys.argv[3], e["seconds"], actual,
      actual / e["seconds"], pass_cpu / cal_cpu))
PY
  done
done
