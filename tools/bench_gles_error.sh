#!/usr/bin/env bash
# GLES against the CPU reference (SPEC metrics): precision fp16/fp32 and the
# error that visibility sub-sampling adds, on cones, fractal and the DEM.
# usage: tools/bench_gles_error.sh [BUILD_DIR] [SIZE]     (defaults: build 128)
set -euo pipefail
cd "$(dirname "$0")/.."
B=${1:-build}
N=${2:-128}
HFS=$B/tools/hfshade
GEN=$B/tools/hfgen
C=$B/bench-cache
mkdir -p "$C"
"$GEN" cones --size ${N}x${N} -o "$C/cones$N.pfm"
"$GEN" fractal --size ${N}x${N} --relief 1 -o "$C/fractalhi$N.pfm"
"$GEN" crop data/jacksboro.png --rect 140,100,$N,$N -o "$C/dem$N.pfm"
scenes=("cones|$C/cones$N.pfm|--dx 1"
        "fractal relief 1|$C/fractalhi$N.pfm|--dx 1"
        "dem|$C/dem$N.pfm|--dx 83 --zscale 2")
lightings=("sky+sun|--env-map data/courtyard.exr --truth-env sh --env-shade sh --key 336,15,2,1500"
           "sky|--env-map data/courtyard.exr --truth-env sh --env-shade sh"
           "sun|--key 336,15,2,1500")
echo "| scene (${N}x${N}) | lights | gles settings | mean abs | RMSE | p99 abs | max abs | non-finite |"
echo "|---|---|---|---|---|---|---|---|"
for sc in "${scenes[@]}"; do
  IFS='|' read -r name hf extra <<<"$sc"
  for li in "${lightings[@]}"; do
    IFS='|' read -r lname L <<<"$li"
    "$HFS" render --height "$hf" $extra $L --backend cpu --subsample 1 --pfm "$C/ref.pfm" --quiet
    for st in "fp16 --subsample 1" "fp32 --subsample 1" "fp16 --subsample 2" "fp16 --subsample 4"; do
        read -r prec rest <<<"$st"
        "$HFS" render --height "$hf" $extra $L --backend gles --precision $prec $rest --pfm "$C/g.pfm" --quiet
        read -r _ mean _ rmse _ p99 _ mx _ nf _ <<<"$("$HFS" compare --height "$hf" $extra $L "$C/g.pfm" "$C/ref.pfm")"
        echo "| $name | $lname | $prec $rest | $mean | $rmse | $p99 | $mx | $nf |"
    done
  done
done
