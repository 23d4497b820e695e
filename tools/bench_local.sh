#!/usr/bin/env bash
# Local lights (issue 4): CPU reference (partial = default, and full swath)
# against ground truth, cones and panel at 128x128, 1/3/8 lights.
# usage: tools/bench_local.sh BUILD_DIR [QUALITY FLAGS...]
set -euo pipefail
cd "$(dirname "$0")/.."
B=$1; shift
Q="$*"
C=$B/bench-local; mkdir -p $C
. tools/bench_local_lights.sh
$B/tools/hfgen cones --size 128x128 -o $C/cones.pfm
$B/tools/hfgen panel --size 128x128 -o $C/panel.pfm
echo "| scene | lights | swath | mean abs | RMSE | p99 abs | max abs | non-finite | rel. mean | cpu s (median of 5) | truth s |"
echo "|---|---|---|---|---|---|---|---|---|---|---|"
for sc in cones panel; do
  for n in 1 3 8; do
    L=""; for ((i=0;i<n;i++)); do if [ $sc = cones ]; then L+=" --local ${CONES[$i]}"; else L+=" --local ${PANEL[$i]}"; fi; done
    truth=$C/truth-$sc-$n.pfm
    [ -s $truth ] || $B/tools/hfshade render --height $C/$sc.pfm $L --backend truth --truth-samples 1024 --pfm $truth 2> $C/truth-$sc-$n.log
    tsec=$(sed -n 's/.*, \([0-9.]*\) s$/\1/p' $C/truth-$sc-$n.log)
    for mode in partial full; do
      out=$C/cpu-$sc-$n-$mode.pfm
      $B/tests/bench_cpu_local --height $C/$sc.pfm $L $Q --swath $mode --repeat 5 --pfm $out 2> $C/cpu.log
      csec=$(sed -n 's/.*median \([0-9.]*\) s.*/\1/p' $C/cpu.log)
      read -r _ mean _ rmse _ p99 _ mx _ nf _ <<<"$($B/tools/hfshade compare --height $C/$sc.pfm $L $out $truth)"
      rel=$(tools/pfm_rel_mean.py "$out" "$truth")
      echo "| $sc | $n | $mode | $mean | $rmse | $p99 | $mx | $nf | $rel | $csec | $tsec |"
    done
  done
done
