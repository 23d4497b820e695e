#!/usr/bin/env bash
# Local lights on the GLES path (issue 4): frame time (median of full frames,
# every pass run), the local-light visibility pass and the shading pass, and
# the error against ground truth (and against the CPU reference), cones and
# panel at 128x128, 1/3/8 lights, partial and full swath, subsample 1 and 2.
# Ground truth is made as tools/bench_local.sh makes it (and shared with it,
# cached in BUILD_DIR/bench-local).  Prints a Markdown table.
# usage: tools/bench_local_gles.sh [BUILD_DIR] [FRAMES]    (defaults: build 5)
set -euo pipefail
cd "$(dirname "$0")/.."
B=${1:-build}
F=${2:-5}
HFS=$B/tools/hfshade
C=$B/bench-local
mkdir -p "$C"
. tools/bench_local_lights.sh
"$B/tools/hfgen" cones --size 128x128 -o "$C/cones.pfm"
"$B/tools/hfgen" panel --size 128x128 -o "$C/panel.pfm"
echo "| scene | lights | swath | sub | GLES frame ms (median of $F) | local pass ms | shade pass ms | mean abs vs truth | rel. mean vs truth | mean abs vs cpu |"
echo "|---|---|---|---|---|---|---|---|---|---|"
for sc in cones panel; do
  for n in 1 3 8; do
    L=""
    for ((i = 0; i < n; i++)); do
      if [ $sc = cones ]; then L+=" --local ${CONES[$i]}"; else L+=" --local ${PANEL[$i]}"; fi
    done
    truth=$C/truth-$sc-$n.pfm
    [ -s "$truth" ] || "$HFS" render --height "$C/$sc.pfm" $L --backend truth --truth-samples 1024 \
                         --pfm "$truth" 2> "$C/truth-$sc-$n.log"
    for mode in partial full; do
      A="--height $C/$sc.pfm $L --local-swath $mode"
      "$HFS" render $A --backend cpu --subsample 1 --pfm "$C/c.pfm" --quiet
      for sub in 1 2; do
        read -r fms lms sms <<<"$("$HFS" render $A --backend gles --subsample $sub --time "$F" --pfm "$C/g.pfm" |
                              awk '$1 == "frame" {f = $2} $1 == "local" {l = $2} $1 == "shade" {s = $2}
                                   END {print f, l, s}')"
        read -r _ mt _ <<<"$("$HFS" compare $A "$C/g.pfm" "$truth")"
        rel=$(tools/pfm_rel_mean.py "$C/g.pfm" "$truth")
        read -r _ mc _ <<<"$("$HFS" compare $A "$C/g.pfm" "$C/c.pfm")"
        echo "| $sc | $n | $mode | $sub | $fms | $lms | $sms | $mt | $rel | $mc |"
      done
    done
  done
done
