#!/usr/bin/env bash
# Fireflies of scenes rendered at their own settings: pixels brighter than 10x the median
# luminance of their 3x3 neighbourhood where a 4096-spp reference has none (`pdrt fireflies`,
# renderer/compare/image_metrics.h), counted by the ratio alone and with a floor of 0.01 in
# luminance (FLOOR=...), and the specks: pixels over 3x the reference's and +0.05. The references (sobol, seed 4242) are rendered once into
# OUT/ref/ and reused; each scene's render goes to OUT/NAME.exr.
# Usage: tools/fireflies.sh [OUT=out/fireflies] [SCENE.json ...] [-- RENDER OPTIONS]
#   default scenes: the demo (scenes/cornell-box.json), gloss-translucency and env-lit;
#   options after -- go to every render of the scenes, not to the references.
set -euo pipefail
out=${1:-out/fireflies}; [ $# -gt 0 ] && shift
scenes=(); opts=()
while [ $# -gt 0 ]; do
  if [ "$1" = -- ]; then shift; opts=("$@"); break; fi
  scenes+=("$1"); shift
done
[ ${#scenes[@]} -eq 0 ] && scenes=(scenes/cornell-box.json scenes/gloss-translucency.json scenes/env-lit.json)
B=${PDRT_BUILD:-build}
mkdir -p "$out/ref"
for scene in "${scenes[@]}"; do
  name=$(basename "$scene" .json)
  ref="$out/ref/$name-4096.exr"
  if [ ! -f "$ref" ]; then  # rendered once: remove it after changing the scene's geometry or lights
    # The reference is unbiased whatever the scene asks: no regularisation, no adaptive stop.
    # A copy beside the scene, so that its relative paths (meshes, textures, sky) still resolve.
    copy="$(dirname "$scene")/.fireflies-ref-$$.json"
    trap 'rm -f "$copy"' EXIT
    python3 - "$scene" "$copy" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
s.get("integrator", {}).pop("regularize", None)
s.get("sampler", {}).pop("adaptive", None)
json.dump(s, open(sys.argv[2], "w"), indent=1)
PY
    "$B/pdrt" render "$copy" --spp 4096 --sampler sobol --seed 4242 -q -o "$ref"
    rm -f "$copy"
  fi
  start=$(date +%s.%N)
  "$B/pdrt" render "$scene" "${opts[@]}" -q -o "$out/$name.exr" -o "$out/$name.png" --stats "$out/$name.json"
  end=$(date +%s.%N)
  literal=$("$B/pdrt" fireflies "$out/$name.exr" --reference "$ref" | sed 's/;.*//')
  count=$("$B/pdrt" fireflies "$out/$name.exr" --reference "$ref" --floor "${FLOOR:-0.01}")
  echo "$scene: $literal; $count; $(python3 -c "print('%.1f s' % ($end - $start))")"
done
