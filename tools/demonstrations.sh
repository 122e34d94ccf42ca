#!/usr/bin/env bash
# The demonstrations of issue 31 item 5: `pdrt compare` on the motion-blur scene
# (scenes/moving-square.json) and the depth-of-field scene (scenes/dof-row.json) at 1, 2, 4 and
# 8 spp, every sampler's seed-0 crop beside its blurred-error heat map (the report's
# images/demonstration.png), with several seeds so that the blurred RMSE has intervals. Copies
# each sheet to DOCS/demo-<scene>.png and prints the blurred RMSE (sigma = 1 px) as a Markdown
# table, and the time each comparison took.
# Usage: tools/demonstrations.sh [OUT]   (default out/demonstrations)
# Environment (defaults in brackets):
#   SAMPLERS  the samplers, comma-separated [jitter,poisson,poisson-ss,poisson-bn,sobol,zsobol]
#   SPP [1,2,4,8]  SEEDS [8]  WIDTH: image width, the height keeps the scene's aspect [128]
#   REF: reference spp [4096]  THREADS [0: all cores]  DOCS: where the sheets go, empty for
#   nowhere [docs/images]  PDRT_BUILD [build]  SCENES [scenes/moving-square.json scenes/dof-row.json]
#   CROPS: per scene NAME=FX,FY,FS, the sheet's square as fractions (x of the width, y and side of
#   the height); a scene not named gets the report's detail window [the two below]
#   CACHE: the reference cache directory [pdrt's default]
set -euo pipefail
OUT=${1:-out/demonstrations}
SAMPLERS=${SAMPLERS:-jitter,poisson,poisson-ss,poisson-bn,sobol,zsobol}
SPP=${SPP:-1,2,4,8}; SEEDS=${SEEDS:-8}; WIDTH=${WIDTH:-128}; REF=${REF:-4096}; THREADS=${THREADS:-0}
DOCS=${DOCS-docs/images}; B=${PDRT_BUILD:-build}
SCENES=${SCENES:-scenes/moving-square.json scenes/dof-row.json}
# The moving square's blurred band across the middle; the defocused red sphere's edge on the yellow one.
CROPS=${CROPS-moving-square=0.3125,0.25,0.5 dof-row=0.17,0.36,0.44}
mkdir -p "$OUT"
[ -n "$DOCS" ] && mkdir -p "$DOCS"
for scene in $SCENES; do
  name=$(basename "$scene" .json)
  height=$(python3 -c 'import json,sys; f=json.load(open(sys.argv[1]))["film"]; print(max(1, round(f["height"]*int(sys.argv[2])/f["width"])))' "$scene" "$WIDTH")
  extra=()
  for c in $CROPS; do
    [ "${c%%=*}" = "$name" ] || continue
    extra+=(--demo-crop "$(python3 -c 'import sys; w, h = int(sys.argv[2]), int(sys.argv[3]); fx, fy, fs = map(float, sys.argv[1].split(",")); print("%d,%d,%d" % (round(fx * w), round(fy * h), round(fs * h)))' "${c#*=}" "$WIDTH" "$height")")
  done
  [ -n "${CACHE:-}" ] && extra+=(--cache-dir "$CACHE")
  echo "== $name (${WIDTH}x$height; $SAMPLERS at $SPP spp, $SEEDS seeds; reference $REF spp) ${extra[*]}"
  start=$(date +%s.%N)
  "$B/pdrt" compare "$scene" --out "$OUT/$name" --samplers "$SAMPLERS" --spp "$SPP" --seeds "$SEEDS" \
    --reference-spp "$REF" --width "$WIDTH" --height "$height" --threads "$THREADS" --quiet "${extra[@]}"
  end=$(date +%s.%N)
  python3 - "$OUT/$name" "$start" "$end" "$DOCS" "$name" <<'PY'
import json, os, shutil, sys
out, start, end, docs, name = sys.argv[1], float(sys.argv[2]), float(sys.argv[3]), sys.argv[4], sys.argv[5]
r = json.load(open(os.path.join(out, "results.json")))
d = r["demonstration"]
if d is None:
    sys.exit("demonstrations.sh: %s: no demonstration sheet (more than 8 samplers or 6 spp)" % out)
print("%s: %.0f s wall; sheet %s (%dx%d, crop %s at (%d, %d), heat scale %.3g)" % (
    name, end - start, os.path.join(out, d["file"]), d["width"], d["height"], d["crop"]["size"], d["crop"]["x"],
    d["crop"]["y"], d["scale"]))
if docs:
    dst = os.path.join(docs, "demo-%s.png" % name)
    shutil.copyfile(os.path.join(out, d["file"]), dst)
    print("copied to %s (%d KB)" % (dst, os.path.getsize(dst) // 1024))
samplers, spps = r["samplers"], r["spp"]
at = {(u["sampler"], u["spp"]): u for u in r["runs"]}
for title, get in (("blurred RMSE, sigma = 1 px", lambda u: (u["blurred_rmse"][0]["rmse"], u["blurred_rmse"][0]["rmse_ci95"])),
                   ("per-pixel RMSE", lambda u: (u["rmse"], u["rmse_ci95"]))):
    print("\n%s (mean of %d seeds +- 95 %% interval; bold: lowest mean)\n" % (title, len(r["seeds"])))
    print("| spp | " + " | ".join(samplers) + " |")
    print("|---:|" + "---:|" * len(samplers))
    for n in spps:
        vals = [get(at[(s, n)]) for s in samplers]
        best = min(v[0] for v in vals)
        cells = [("**%.4f** +- %.4f" if v[0] == best else "%.4f +- %.4f") % v for v in vals]
        print("| %d | %s |" % (n, " | ".join(cells)))
print()
PY
done
