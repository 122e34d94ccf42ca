#!/usr/bin/env bash
# Time per sample of pdrt vs Embree's own tutorial path tracer (Debian embree-tools,
# `pathtracer`) on the same >= 500k-triangle OBJ, camera, resolution, spp, path length and
# threads, lit by a constant white environment / ambient light.
# Each renderer runs at N and 2N spp; the difference of the wall times is the time of N
# samples per pixel, so loading and BVH building cancel out.
# Usage: bench/compare_embree_pathtracer.sh [BUILD_DIR=build] [OUT_DIR=out/bench] [N=16] [THREADS=2] [DEPTH=4]
set -euo pipefail
B=${1:-build}; O=${2:-out/bench}; N=${3:-16}; T=${4:-2}; D=${5:-4}
mkdir -p "$O"
"$B/bench/make_bench_scene" "$O" >/dev/null
W=640; H=480
now() { date +%s.%N; }
run_pdrt() {  # spp
  "$B/pdrt" render "$O/bench.json" -o "$O/pdrt-$1.exr" --spp "$1" --threads "$T" --quiet
}
run_embree() {  # spp
  pathtracer -i "$O/bench.obj" --vp 0 1.2 3.2 --vi 0 0.2 0 --vu 0 1 0 --fov 45 --size $W $H \
    --spp "$1" --max-path-length "$D" --ambientlight 1 1 1 --threads "$T" -o "$O/embree-$1.ppm" >/dev/null 2>&1
}
sed -i "s/\"max_depth\": [0-9]*/\"max_depth\": $D/" "$O/bench.json"
declare -A secs
for who in pdrt embree; do
  for spp in "$N" "$((2 * N))"; do
    best=1e9
    for rep in 1 2 3; do  # best of three: the machine is shared
      s=$(now); "run_$who" "$spp"; e=$(now)
      best=$(awk -v s="$s" -v e="$e" -v b="$best" 'BEGIN { t = e - s; print (t < b ? t : b) }')
    done
    secs[$who,$spp]=$best
  done
done
for who in pdrt embree; do
  per=$(awk -v a="${secs[$who,$N]}" -v b="${secs[$who,$((2 * N))]}" -v n=$((W * H * N)) 'BEGIN { print (b - a) / n * 1e9 }')
  printf "%-7s %4d spp: %.3f s, %4d spp: %.3f s -> %.1f ns per sample (path length %d, %d threads)\n" \
    "$who" "$N" "${secs[$who,$N]}" "$((2 * N))" "${secs[$who,$((2 * N))]}" "$per" "$D" "$T"
done
