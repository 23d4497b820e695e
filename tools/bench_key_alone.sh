#!/usr/bin/env bash
# A key light alone against the truth, two builds side by side (issue 36:
# the key light's own cell): the 2-degree sun 15 degrees up (336/15) on the
# benchmark scenes at 128² (cones, the fractal at relief 0.25, the DEM
# window, the fractal at relief 1) and hfgen's Hurst-0.25 and Hurst-0.8
# fields at 64², at subsample 2 and 1; prints the mean and p99 error of
# each build (hfshade compare: fractions of the unshadowed maximum).
#   tools/bench_key_alone.sh OLD/build NEW/build
set -euo pipefail
cd "$(dirname "$0")/.."
. tools/bench_lib.sh
OLD=${1:?old build}
NEW=${2:?new build}
GEN=$NEW/tools/hfgen
C=$NEW/bench-cache
mkdir -p "$C"
bench_rough_scenes "$GEN" "$C" 128
L=(--key "336,15,2,1500")
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
echo "| scene | subsample | old mean / p99 | new mean / p99 |"
echo "|---|---|---|---|"
for sc in "${scenes[@]}"; do
    IFS='|' read -r name hf extra <<<"$sc"
    read -r -a ex <<<"$extra"
    truth=$C/key-truth-${hf##*/}
    bench_truth "$NEW/tools/hfshade" "$truth" --height "$hf" "${ex[@]}" "${L[@]}"
    for sub in 2 1; do
        row="| $name | $sub"
        for B in "$OLD" "$NEW"; do
            "$B/tools/hfshade" render --height "$hf" "${ex[@]}" "${L[@]}" --subsample "$sub" \
                --quiet --pfm "$T/out.pfm"
            read -r _ mean _ _ _ p99 _ < <("$NEW/tools/hfshade" compare --height "$hf" \
                "${ex[@]}" "${L[@]}" "$T/out.pfm" "$truth")
            row="$row | $mean / $p99"
        done
        echo "$row |"
    done
done
