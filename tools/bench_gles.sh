#!/usr/bin/env bash
# GLES renderer frame times (median of full frames, every pass run: caches
# invalidated) and texture memory, next to the CPU reference's time for the
# same frame measured in the same run.  Prints a Markdown table.
# usage: tools/bench_gles.sh [BUILD_DIR] [FRAMES]      (defaults: build 5)
set -euo pipefail
cd "$(dirname "$0")/.."
B=${1:-build}
F=${2:-5}
HFS=$B/tools/hfshade
C=$B/bench-cache
mkdir -p "$C"
SKY="--env-sh 3.5449077,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0"
SUN="--key 336,15,2,1500"
# frame_ms ARGS... -> "median_frame_ms texture_MiB"
frame_ms() {
    "$HFS" render "$@" --time "$F" --pfm "$C/gles-time.pfm" |
        awk '$1 == "frame" {f = $2} /^texture memory/ {m = $3} END {print f, m}'
}
echo "| size | lights | subsample | precision | GLES frame ms (median of $F) | fps | texture MiB | CPU reference ms (median of 3) |"
echo "|---|---|---|---|---|---|---|---|"
for n in 128 256 512; do
    "$B/tools/hfgen" fractal --size ${n}x${n} -o "$C/frac$n.pfm"
    for li in "env|$SKY" "key|$SUN" "env+key|$SKY $SUN"; do
        IFS='|' read -r lname L <<<"$li"
        cpu=$(F=3 frame_ms --height "$C/frac$n.pfm" $L --backend cpu --subsample 1 | cut -d' ' -f1)
        for sub in 1 2 4; do
            for prec in fp16 fp32; do
                read -r ms mib <<<"$(frame_ms --height "$C/frac$n.pfm" $L --backend gles --subsample $sub --precision $prec)"
                fps=$(awk -v m="$ms" 'BEGIN {printf "%.1f", 1000 / m}')
                echo "| ${n}x${n} | $lname | $sub | $prec | $ms | $fps | $mib | $cpu |"
            done
        done
    done
done
