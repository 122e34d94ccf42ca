#!/usr/bin/env bash
# RMSE of two pdrt builds' renders against one 4096-spp reference, at equal samples and at
# equal time, side by side in one run (issue 14's acceptance table).
#   bench/rmse_before_after.sh OLD_PDRT NEW_PDRT OUT_DIR [SCALE]
# SCALE divides each scene's resolution (default 2). Renders are linear TIFF (RGB only) so
# that `idiff` measures the colour channels. Each build is measured against its own reference
# (sobol, REF_SPP = 4096 spp, another seed), so the RMSE is noise, not the difference between
# what the two builds converge to. Prints a markdown table; OUT_DIR keeps images and stats.
set -euo pipefail
old=$1 new=$2 out=$3 scale=${4:-2}
here=$(cd "$(dirname "$0")/.." && pwd)
mkdir -p "$out"
rms() { { idiff -a "$1" "$2" 2>/dev/null || true; } | sed -n 's/.*RMS error = \([0-9.e+-]*\).*/\1/p' | head -1; }
secs() { python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['seconds'])" "$1"; }
echo "| scene | spp | before RMSE | after RMSE | ratio | before s | after s | after RMSE at before's time | ratio |"
echo "|---|---|---|---|---|---|---|---|---|"
for scene in ${SCENES:-dof-row pool-balls cornell-box soft-shadows}; do
  f=$here/scenes/$scene.json
  read -r w h < <(python3 -c "import json,sys; d=json.load(open(sys.argv[1]))['film']; print(d['width']//$scale, d['height']//$scale)" "$f")
  declare -A e t
  for who in before after; do
    bin=$old; [ $who = after ] && bin=$new
    ref=$out/$scene-$who-ref.tif
    [ -f "$ref" ] || "$bin" render "$f" --width "$w" --height "$h" --sampler sobol --seed 987654321 \
      --spp "${REF_SPP:-4096}" -o "$ref" --quiet --allow-long-render
    for spp in 16 64 256; do
      img=$out/$scene-$who-$spp.tif
      "$bin" render "$f" --width "$w" --height "$h" --spp "$spp" -o "$img" --stats "$out/$scene-$who-$spp.json" --quiet
      e[$who$spp]=$(rms "$img" "$ref")
      t[$who$spp]=$(secs "$out/$scene-$who-$spp.json")
    done
  done
  for spp in 16 64 256; do
    # After's RMSE interpolated (log-log in time) at before's render time.
    eq=$(python3 - "${t[before$spp]}" "${t[after16]}" "${e[after16]}" "${t[after64]}" "${e[after64]}" "${t[after256]}" "${e[after256]}" <<'PY'
import math, sys
T = float(sys.argv[1]); pts = [(float(sys.argv[i]), float(sys.argv[i + 1])) for i in (2, 4, 6)]
pts.sort()
lt = math.log(T)
for (t0, e0), (t1, e1) in zip(pts, pts[1:]):
    if t0 <= T <= t1 or (T < pts[0][0] and (t0, e0) == pts[0]) or (T > pts[-1][0] and (t1, e1) == pts[-1]):
        a = (lt - math.log(t0)) / (math.log(t1) - math.log(t0))
        print(f"{math.exp(math.log(e0) + a * (math.log(e1) - math.log(e0))):.5f}"); break
PY
)
    python3 -c "
b,a,tb,ta,eq=[float(x) for x in '${e[before$spp]} ${e[after$spp]} ${t[before$spp]} ${t[after$spp]} $eq'.split()]
print(f'| $scene ${w}x${h} | $spp | {b:.5f} | {a:.5f} | {b/a:.2f}x | {tb:.2f} | {ta:.2f} | {eq:.5f} | {b/eq:.2f}x |')"
  done
  unset e t
done
