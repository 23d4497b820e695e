#!/usr/bin/env bash
# The truth's exact horizons (issue 36): how far the environment truth moved
# from a build whose horizons were a 0.25-texel march, and what it costs.
# The truth of each build under the courtyard sky's order-4 projection, on
# the benchmark scenes at N x N, the roughest fractal (relief 1) and hfgen's
# Hurst-0.25 and Hurst-0.8 fields at 64x64 (issue 36 item 4's); prints the
# new truth against the old one (hfshade compare: fractions of the
# unshadowed maximum) and each truth's wall time.
#   tools/bench_truth_horizon.sh OLD/build NEW/build [N]     (default N 128)
set -euo pipefail
cd "$(dirname "$0")/.."
. tools/bench_lib.sh
OLD=${1:?old build}
NEW=${2:?new build}
N=${3:-128}
GEN=$NEW/tools/hfgen
C=$NEW/bench-cache
mkdir -p "$C"
bench_rough_scenes "$GEN" "$C" "$N"
SKY=(--env-map data/courtyard.exr --truth-env sh)
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
echo "| scene | new truth - old: mean abs | p99 abs | max abs | old truth s | new truth s |"
echo "|---|---|---|---|---|---|"
for sc in "${scenes[@]}"; do
    IFS='|' read -r name hf extra <<<"$sc"
    read -r -a ex <<<"$extra"
    declare -A secs
    for b in old new; do
        B=$OLD
        [ "$b" = new ] && B=$NEW
        t0=$(date +%s.%N)
        "$B/tools/hfshade" render --height "$hf" "${ex[@]}" "${SKY[@]}" --backend truth \
            --quiet --pfm "$T/$b.pfm"
        t1=$(date +%s.%N)
        secs[$b]=$(echo "$t1 - $t0" | bc)
    done
    read -r _ mean _ _ _ p99 _ max _ < <("$NEW/tools/hfshade" compare --height "$hf" "${ex[@]}" \
        "${SKY[@]}" "$T/new.pfm" "$T/old.pfm")
    printf '| %s | %s | %s | %s | %.2f | %.2f |\n' "$name" "$mean" "$p99" "$max" "${secs[old]}" \
        "${secs[new]}"
done
