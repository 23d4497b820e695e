#!/usr/bin/env bash
# Local lights on the GLES path: frame time (median of full frames, every pass
# run) and error against the CPU reference, cones and panel at 128x128,
# 1/3/8 lights, partial and full swath.  Prints a Markdown table.
# usage: tools/bench_local_gles.sh [BUILD_DIR] [FRAMES]    (defaults: build 5)
set -euo pipefail
cd "$(dirname "$0")/.."
B=${1:-build}
F=${2:-5}
HFS=$B/tools/hfshade
C=$B/bench-local
mkdir -p "$C"
# The same lights as tools/bench_local.sh.
CONES=(64,64,12,2,100 20,20,6,1.5,60 100,110,25,3,150 50,110,4,1,40 110,60,8,1,50 70,15,3,1,30 30,70,15,2,80 90,80,30,4,200)
PANEL=(48,48,7,1.5,50 80,20,6,1,40 20,80,9,2,60 112,100,3,0.8,30 60,90,8,1,50 16,16,6,1,40 100,48,10,2,80 40,110,5,1,40)
"$B/tools/hfgen" cones --size 128x128 -o "$C/cones.pfm"
"$B/tools/hfgen" panel --size 128x128 -o "$C/panel.pfm"
echo "| scene | lights | swath | GLES frame ms (median of $F) | GLES shade pass ms | mean abs vs cpu | max abs vs cpu |"
echo "|---|---|---|---|---|---|---|"
for sc in cones panel; do
  for n in 1 3 8; do
    L=""
    for ((i = 0; i < n; i++)); do
      if [ $sc = cones ]; then L+=" --local ${CONES[$i]}"; else L+=" --local ${PANEL[$i]}"; fi
    done
    for mode in partial full; do
      A="--height $C/$sc.pfm $L --local-swath $mode"
      read -r fms sms <<<"$("$HFS" render $A --backend gles --subsample 1 --time "$F" --pfm "$C/g.pfm" |
                          awk '$1 == "frame" {f = $2} $1 == "shade" {s = $2} END {print f, s}')"
      "$HFS" render $A --backend cpu --pfm "$C/c.pfm" --quiet
      read -r _ mean _ _ _ _ _ mx _ <<<"$("$HFS" compare $A "$C/g.pfm" "$C/c.pfm")"
      echo "| $sc | $n | $mode | $fms | $sms | $mean | $mx |"
    done
  done
done
