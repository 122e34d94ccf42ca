#!/usr/bin/env bash
# Renders the `pdrt compare` report of every scene in scenes/ (scenes/*.json and the pbrt-v4
# scenes scenes/pbrt/*/*.pbrt) with the same settings (no per-scene tuning) into
# OUT/<scene>/index.html.
# Usage: tools/compare-all.sh [OUT [SCALE [SPP [REF_SPP [SEEDS]]]]]   (positional; defaults
#   out/compare 1 1,4,16,64,256 4096 4). SCALE divides each scene's resolution (2 = half width
#   and height) to save time. The adaptive sweep targets the uniform RMSE at 64 spp when SPP
#   holds 64, else at SPP's largest count.
# MODE=plan writes every scene's comparison as a plan (OUT/<scene>/plan.json) and OUT/jobs.txt,
# one "DIR INDEX" line per job of every plan, to run anywhere (docs/distributed.md), e.g.
#   xargs -P 2 -L 1 build/pdrt run-job --quiet < OUT/jobs.txt
# then MODE=collect writes every report and the summary.
set -euo pipefail
OUT=${1:-out/compare}; SCALE=${2:-1}; SPP=${3:-1,4,16,64,256}; REF=${4:-4096}; SEEDS=${5:-4}
case ",$SPP," in *,64,*) TARGET=64 ;; *) TARGET=${SPP##*,} ;; esac
B=${PDRT_BUILD:-build}; MODE=${MODE:-run}
case "$MODE" in run|plan|collect) ;; *) echo "compare-all.sh: MODE must be run, plan or collect, got \"$MODE\"" >&2; exit 2 ;; esac
mkdir -p "$OUT"
[ "$MODE" = plan ] && : > "$OUT/jobs.txt"
shopt -s nullglob
for scene in scenes/*.json scenes/pbrt/*/*.pbrt; do
  name=$(basename "$scene"); name=${name%.*}
  if [ "$MODE" = collect ]; then
    "$B/pdrt" collect "$OUT/$name" --quiet
    continue
  fi
  read -r w h < <(tools/film-size.py "$scene" "$SCALE")  # pbrt: 1280x720 unless the Film says
  echo "== $name (${w}x${h}, spp $SPP, $SEEDS seeds, reference $REF spp)"
  if [ "$MODE" = plan ]; then
    target=(--plan "$OUT/$name" --quiet)
  else
    target=(--out "$OUT/$name")
  fi
  "$B/pdrt" compare "$scene" "${target[@]}" --samplers random,jitter,poisson,poisson-065,sobol --spp "$SPP" \
    --seeds "$SEEDS" --reference-spp "$REF" --width "$w" --height "$h" --adaptive --adaptive-target-spp "$TARGET"
  if [ "$MODE" = plan ]; then sed "s|^|$OUT/$name |" "$OUT/$name/jobs.txt" >> "$OUT/jobs.txt"; fi
done
if [ "$MODE" = plan ]; then
  echo "wrote $(wc -l < "$OUT/jobs.txt") jobs to $OUT/jobs.txt; run them, then MODE=collect $0 $*"
  exit 0
fi
# One summary table over all scenes: mean RMSE +- 95 % interval per sampler at each spp, the
# best (a tie with every sampler whose interval overlaps the best's), and the fitted slopes;
# then the screen-space measures' means (blurred RMSE at sigma 1 px / low-frequency share / HDR-FLIP).
/usr/bin/env python3 - "$OUT" <<'PY'
import json, os, sys
out = sys.argv[1]
rows, screen, names, one_seed = [], [], [], False
for name in sorted(os.listdir(out)):
    p = os.path.join(out, name, "results.json")
    if not os.path.exists(p):
        continue
    r = json.load(open(p))
    names = r["samplers"]
    # One seed has no interval: the lowest RMSE only, no ± and no ties.
    single = len(r.get("seeds", [0])) < 2
    one_seed = one_seed or single
    for n in r["spp"]:
        e = {u["sampler"]: (u["rmse"], u.get("rmse_ci95", 0.0)) for u in r["runs"] if u["spp"] == n}
        best = min(e, key=lambda s: e[s][0])
        tied = [] if single else [s for s in r["samplers"] if s != best and e[s][0] - e[s][1] <= e[best][0] + e[best][1]]
        verdict = best if not tied else "tie: " + ", ".join([best] + tied)
        cells = ("%.4g" % e[s][0] if single else "%.4g ± %.2g" % e[s] for s in r["samplers"])
        rows.append("| %s | %d | %s | %s |" % (name, n, " | ".join(cells), verdict))
        if all("blurred_rmse" in u for u in r["runs"]):
            m = {u["sampler"]: u for u in r["runs"] if u["spp"] == n}
            screen.append("| %s | %d | %s |" % (name, n, " | ".join("%.4g / %.3f / %.4f" % (
                m[s]["blurred_rmse"][0]["rmse"], m[s]["low_frequency_share"]["mean"] or float("nan"),
                m[s]["flip"]["hdr"]["mean"]) for s in r["samplers"])))
    rows.append("| %s | slope | %s | |" % (name, " | ".join("%.2f" % r["slopes"][s] for s in r["samplers"])))
with open(os.path.join(out, "summary.md"), "w") as f:
    f.write("| scene | spp | " + " | ".join(names) + " | best |\n|---|---|" + "---|" * (len(names) + 1) + "\n")
    f.write("\n".join(rows) + "\n")
    if screen:
        f.write("\nScreen-space measures, means over seeds (docs/renderer.md, \"The compare report\"): RMSE of the "
                "error blurred by sigma = 1 px / share of the error power below 1/4 cycle per pixel (white: 0.196) "
                "/ mean HDR-FLIP; lower is better.\n\n| scene | spp | " + " | ".join(names) + " |\n|---|---|" +
                "---|" * len(names) + "\n")
        f.write("\n".join(screen) + "\n")
    if one_seed:
        f.write("\nOne seed: no intervals, so no ties; \"best\" is the lowest RMSE of one sample of each. "
                "Intervals and ties need --seeds 2 or more (SEEDS, the fifth argument).\n")
print("wrote", os.path.join(out, "summary.md"))
PY
