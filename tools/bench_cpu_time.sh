#!/usr/bin/env bash
# Wall time of the CPU reference (and, for scale, of the ground truth at a
# smaller size): median of R runs.  Prints a Markdown table.
# usage: tools/bench_cpu_time.sh [BUILD_DIR] [RUNS]
set -euo pipefail
cd "$(dirname "$0")/.."
B=${1:-build}
R=${2:-5}
HFS=$B/tools/hfshade
C=$B/bench-cache
mkdir -p "$C"
SKY="--env-sh 3.5449077,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0"
SUN="--key 336,15,2,1500"

median() { sort -g | awk '{a[NR]=$1} END {print (NR % 2) ? a[(NR+1)/2] : (a[NR/2] + a[NR/2+1]) / 2}'; }
run() { # run N ARGS... : median wall seconds reported by hfshade
    local n=$1; shift
    for _ in $(seq "$n"); do
        "$HFS" render "$@" --pfm "$C/time.pfm" 2>&1 | sed -n 's/.*, \([0-9.]*\) s$/\1/p'
    done | median
}
echo "| size | lights | backend | settings | threads | median wall s (runs) |"
echo "|---|---|---|---|---|---|"
for n in 128 256 512; do
    "$B/tools/hfgen" fractal --size ${n}x${n} -o "$C/frac$n.pfm"
    for li in "env|$SKY" "env+key|$SKY $SUN"; do
        IFS='|' read -r lname L <<<"$li"
        for vis in legendre wedge; do
            t=$(run "$R" --height "$C/frac$n.pfm" $L --backend cpu --visibility $vis)
            echo "| ${n}x${n} | $lname | cpu | default ($vis) | $(nproc) | $t ($R) |"
        done
    done
done
t=$(run 1 --height "$C/frac128.pfm" $SKY $SUN --backend truth)
echo "| 128x128 | env+key | truth | 720 azimuths, 256 samples | $(nproc) | $t (1) |"
