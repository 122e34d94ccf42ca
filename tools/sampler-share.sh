#!/usr/bin/env bash
# The sampler's share of render CPU (SamplerProfiler, `pdrt render --stats` sampler_share) for
# every sampler on every scene compare-all.sh renders (scenes/*.json, scenes/pbrt/*/*.pbrt), each
# at its own film size divided by SCALE and SPP samples per pixel; prints a markdown table
# (share in %, the largest per sampler in the last row) and keeps the stats files in OUT.
# poisson-ip renders with splat reconstruction (the others with the scene's).
# Usage: tools/sampler-share.sh [OUT [SCALE [SPP [THREADS]]]]   (defaults out/sampler-share 2 64 1)
set -euo pipefail
OUT=${1:-out/sampler-share}; SCALE=${2:-2}; SPP=${3:-64}; T=${4:-1}
B=${PDRT_BUILD:-build}
SAMPLERS=${SAMPLERS:-random jitter poisson poisson-065 sobol pmj02bn zsobol regular poisson-ss poisson-bn poisson-ip}
mkdir -p "$OUT"
shopt -s nullglob
for scene in scenes/*.json scenes/pbrt/*/*.pbrt; do
  name=$(basename "$scene"); name=${name%.*}
  read -r w h < <(tools/film-size.py "$scene" "$SCALE")
  for s in $SAMPLERS; do
    extra=()
    [ "$s" = poisson-ip ] && extra=(--reconstruction splat)  # it renders only by splatting
    "$B/pdrt" render "$scene" -o "$OUT/$name-$s.exr" --sampler "$s" --spp "$SPP" --width "$w" --height "$h" \
      --threads "$T" --stats "$OUT/$name-$s.json" --quiet "${extra[@]}"
  done
done
/usr/bin/env python3 - "$OUT" $SAMPLERS <<'PY'
import glob, json, os, sys
out, samplers = sys.argv[1], sys.argv[2:]
stats = {}
for p in glob.glob(os.path.join(out, "*.json")):
    j = json.load(open(p))
    stats[(os.path.splitext(os.path.basename(j["scene"]))[0], j["sampler"])] = j
scenes = sorted({k[0] for k in stats})
print("| scene | " + " | ".join(samplers) + " |")
print("|---|" + "---|" * len(samplers))
worst = {s: 0.0 for s in samplers}
for n in scenes:
    cells = []
    for s in samplers:
        sh = stats[(n, s)]["sampler_share"]
        share = 100 * (sh["share"] or 0.0)
        worst[s] = max(worst[s], share)
        cells.append("%.1f ± %.1f" % (share, 100 * (sh["standard_error"] or 0.0)))
    print("| %s | %s |" % (n, " | ".join(cells)))
print("| **largest** | " + " | ".join("**%.1f**" % worst[s] for s in samplers) + " |")
PY
