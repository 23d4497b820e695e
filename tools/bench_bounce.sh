#!/usr/bin/env bash
# Indirect light against the ground truth (issue 16): for bounces 0..3 on
# the benchmark scenes (cones, the fractal at relief 0.25, the DEM window)
# under the demo's sky + sun, the CPU reference against the truth with the
# same bounces: the whole image's mean and p99 error (fractions of the
# unshadowed maximum), the indirect part alone (image(B) - image(0))
# against the truth's (mean error over its largest value, its 99th
# percentile, and the mean signed error over the same: its bias), and the wall
# time of each (this machine's cores).  The truth is that of the sky's SH
# projection and the renderers light the sky through it too (truth-env=sh,
# env-shade=sh): the bounces' error, not the projection's.  (Until 49bf4a5
# the renderers shaded the map itself, env-shade's default since issue 17,
# against the SH truth: their direct light's difference from the truth's,
# 2.6% of the unshadowed maximum on Hurst-0.25 relief, went into what the
# bounces gathered.)  Prints a Markdown table.
# usage: tools/bench_bounce.sh [BUILD_DIR] [SIZE] [TRUTH_SAMPLES] [BACKENDS] [MAX_BOUNCES] [ALBEDO]
#        (defaults: build 128 256 cpu 3 uniform; BACKENDS e.g. cpu,gles: each against the
#        same truth; ALBEDO "map": each scene lit with `hfgen albedo` of its heights,
#        vegetation below and rock above, instead of albedo 1; "glossy": albedo 0.7 +
#        specular 0.3, gloss 16, seen from azimuth 200, elevation 35)
set -euo pipefail
cd "$(dirname "$0")/.."
# shellcheck source=tools/bench_lib.sh
. tools/bench_lib.sh
B=${1:-build}
N=${2:-128}
S=${3:-256}
BE=${4:-cpu}
MB=${5:-3}
AL=${6:-uniform}
C=$B/bench-cache
mkdir -p "$C"
bench_scenes "$B/tools/hfgen" "$C" "$N"
echo "| scene (${N}x${N}) | backend | bounces | mean abs | p99 abs | indirect alone | its p99 | its bias | backend s | truth s |"
echo "|---|---|---|---|---|---|---|---|---|---|"
for sc in "${scenes[@]}"; do
    bench_scene_keys "$sc"
    if [ "$AL" = map ]; then
        "$B/tools/hfgen" albedo "$hf" -o "${hf%.pfm}-albedo.pfm"
        keys+=("albedo-map=${hf%.pfm}-albedo.pfm")
    elif [ "$AL" = glossy ]; then
        keys+=(albedo=0.7 specular=0.3 gloss=16 view-dir=200,35)
    fi
    "$B/tests/bench_bounce" "$name" "backends=$BE" "max-bounces=$MB" "height=$hf" "${keys[@]}" env-map=data/courtyard.exr \
        key=336,15,2,1500 "truth-samples=$S" truth-env=sh env-shade=sh
done
