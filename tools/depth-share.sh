#!/usr/bin/env bash
# Share of a scene's image that comes from light scattered at three or more surfaces:
#   share = 1 - mean(Y at max_depth 2) / mean(Y at the scene's max_depth)
# Y = 0.2126 R + 0.7152 G + 0.0722 B, the mean over every pixel. max_depth counts the
# surfaces a path scatters at (docs/renderer.md): max_depth 2 keeps emitters seen directly,
# direct light (one scattering) and one indirect bounce (two), so the rest is the light of
# paths with >= 3 scattering vertices before the light (scenes/README.md).
# Usage: tools/depth-share.sh SCENE [SPP=1024] [WIDTH HEIGHT]
#   SCENE is pdrt JSON or pbrt-v4; the copy with max_depth 2 is written beside it (relative
#   paths in it keep working) and removed afterwards. Both renders use the same seed.
set -euo pipefail
scene=$1; spp=${2:-1024}; size=()
[ $# -ge 4 ] && size=(--width "$3" --height "$4")
B=${PDRT_BUILD:-build}
dir=$(dirname "$scene"); base=$(basename "$scene"); ext=${base##*.}
tmp=$(mktemp -d)
copy="$dir/.depth2-$$.$ext"
trap 'rm -rf "$tmp" "$copy"' EXIT
if [ "$ext" = pbrt ]; then
  # pbrt: replace the Integrator directive (with its parameter lines) by one of maxdepth 2.
  python3 - "$scene" "$copy" <<'PY'
import re, sys
text = open(sys.argv[1]).read()
new = 'Integrator "path" "integer maxdepth" [ 2 ]\n'
pat = re.compile(r'^Integrator\s+"[^"]*"(?:\s*"[^"]*"\s*\[[^\]]*\])*[^\n]*\n', re.M)
if pat.search(text):
    text = pat.sub(new, text, count=1)
else:
    text = new + text  # options block: before WorldBegin, so at the top is fine
open(sys.argv[2], "w").write(text)
PY
else
  python3 - "$scene" "$copy" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
s.setdefault("integrator", {})["max_depth"] = 2
json.dump(s, open(sys.argv[2], "w"), indent=1)
PY
fi
lum() {  # mean luminance of an EXR's R, G, B
  oiiotool "$1" --ch R,G,B --printstats | awk '/Stats Avg/ {printf "%.9g\n", 0.2126*$3 + 0.7152*$4 + 0.0722*$5}'
}
start=$(date +%s.%N)
"$B/pdrt" render "$scene" --spp "$spp" "${size[@]}" -q -o "$tmp/full.exr"
mid=$(date +%s.%N)
"$B/pdrt" render "$copy" --spp "$spp" "${size[@]}" -q -o "$tmp/d2.exr"
full=$(lum "$tmp/full.exr"); d2=$(lum "$tmp/d2.exr")
python3 -c "
full, d2, t = $full, $d2, $mid - $start
print('%s: mean Y %.6g (scene max_depth), %.6g (max_depth 2); depth>=3 share %.3f; %d spp in %.1f s' % ('$scene', full, d2, 1 - d2 / full, $spp, t))"
