#!/usr/bin/env bash
# Pixel hashes of every scene in scenes/ (JSON and pbrt) x every sampler x the three
# reconstructions x adaptive off and on, small and fast, plus 2 MPI ranks against 1 for each
# scene. A refactoring that must not change images compares two manifests with diff:
#   tools/image-hashes.sh before.txt          # on the old commit
#   tools/image-hashes.sh after.txt && diff before.txt after.txt
# A refused combination is recorded with its exit status and the first line of its message, so
# errors must stay the same too. PDRT_BUILD picks the build folder (default build), JOBS the
# parallel renders (default: the cores), SAMPLERS the samplers (default: the six below).
# Usage: tools/image-hashes.sh MANIFEST [SCENE ...]
set -euo pipefail
[ $# -ge 1 ] || { echo "usage: tools/image-hashes.sh MANIFEST [SCENE ...]" >&2; exit 2; }
manifest=$1; shift
B=$(cd "${PDRT_BUILD:-build}" && pwd)
scenes=("$@")
if [ ${#scenes[@]} -eq 0 ]; then
  mapfile -t scenes < <(ls scenes/*.json scenes/examples/*.json scenes/pbrt/*/*.pbrt | sort)
fi
samplers=(${SAMPLERS:-random jitter poisson poisson-065 sobol regular})  # SAMPLERS="a b" to choose
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# One line per render: scene sampler reconstruction adaptive ranks
for scene in "${scenes[@]}"; do
  for sampler in "${samplers[@]}"; do
    for rec in importance splat rank; do
      for adaptive in off on; do echo "$scene $sampler $rec $adaptive 1"; done
    done
  done
  for adaptive in off on; do echo "$scene poisson importance $adaptive 2"; done
done > "$work/jobs"

render_one() {
  local scene=$1 sampler=$2 rec=$3 adaptive=$4 ranks=$5 B=$6 work=$7
  local key="$scene $sampler $rec adaptive=$adaptive ranks=$ranks"
  local out="$work/$(echo "$key" | tr ' /=' '___').exr"
  local args=(render "$scene" --sampler "$sampler" --reconstruction "$rec" --width 24 --height 16
              --seed 7 -q -o "$out" --threads 1)
  if [ "$adaptive" = on ]; then args+=(--min-spp 2 --max-spp 8); else args+=(--spp 4); fi
  local rc=0 err
  if [ "$ranks" = 1 ]; then
    err=$("$B/pdrt" "${args[@]}" 2>&1 >/dev/null) || rc=$?
  else
    err=$(OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 \
          mpirun -np "$ranks" --bind-to none --oversubscribe "$B/pdrt" "${args[@]}" 2>&1 >/dev/null) || rc=$?
  fi
  if [ $rc -eq 0 ]; then
    echo "$key: $(iinfo --hash "$out" | sed -n 's/.*SHA-1: *//p')"
  else
    # Messages name the output path, which is a temporary name: drop it.
    echo "$key: exit $rc: $(echo "$err" | head -n 1 | sed "s#$work/[^ :]*#OUT#g")"
  fi
  rm -f "$out"
}
export -f render_one
xargs -P "${JOBS:-$(nproc)}" -L 1 bash -c 'render_one "$@" '"$B $work" _ < "$work/jobs" | sort > "$manifest"
echo "$(wc -l < "$manifest") images and refusals in $manifest ($(grep -c ': exit ' "$manifest" || true) refused)"
