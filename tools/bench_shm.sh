#!/usr/bin/env bash
# Shadow height maps against the truth (issue 19): on the benchmark scenes
# (cones, the fractal at relief 0.25, the DEM window; tools/bench_lib.sh)
# at SIZE^2 under the demo's sun (336/15 degrees, radius ALPHA), points near
# its shadow edges (tests/shm_points.h), each backend's visible fractions
# against the truth's exact rays and its query time (tests/bench_shm.c).
# Prints Markdown rows.
# usage: tools/bench_shm.sh [BUILD_DIR] [SIZE] [BACKENDS] [ALPHA] [POINTS]
#        (defaults: build 256 cpu,gles 2 1000)
set -euo pipefail
cd "$(dirname "$0")/.."
# shellcheck source=tools/bench_lib.sh
. tools/bench_lib.sh
B=${1:-build}
N=${2:-256}
BE=${3:-cpu,gles}
A=${4:-2}
P=${5:-1000}
C=$B/bench-cache
mkdir -p "$C"
bench_scenes "$B/tools/hfgen" "$C" "$N"
echo "| scene | backend | points | mean abs vs truth | wrong side of 1/2 | query ms | truth s |"
echo "|---|---|---|---|---|---|---|"
for sc in "${scenes[@]}"; do
    bench_scene_keys "$sc"
    "$B/tests/bench_shm" "$name" "backends=$BE" "points=$P" "height=$hf" "${keys[@]}" \
        "key=336,15,$A,1500" truth-samples=1024
done
