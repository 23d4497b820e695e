#!/usr/bin/env bash
# CPU reference against ground truth (SPEC's four error metrics) on cones,
# fractal terrain and the real DEM, at the default settings and heavier ones,
# with the wall time of each backend.  Prints a Markdown table (BENCHMARKS.md).
#
# usage: tools/bench_reference.sh [BUILD_DIR] [SIZE]     (defaults: build 128)
# Truth renders are cached in $BUILD_DIR/bench-cache by scene and settings.
set -euo pipefail
cd "$(dirname "$0")/.."
# shellcheck source=tools/bench_lib.sh
. tools/bench_lib.sh
B=${1:-build}
N=${2:-128}
HFS=$B/tools/hfshade
GEN=$B/tools/hfgen
C=$B/bench-cache
mkdir -p "$C"

# Scenes (tools/bench_lib.sh): name, height file, extra scene flags.
bench_scenes "$GEN" "$C" "$N"
# Lightings: the demo scene's sky and low sun together, and the sun alone
# (where horizon accuracy, not SH order, dominates the error).
lightings=("sky+sun|--env-map data/courtyard.exr --truth-env sh --env-shade sh --key 336,15,2,1500"
           "sun|--key 336,15,2,1500")

# Quality settings: label and flags (k, offset, directions, visibility path;
# "default" is issue 2's, Legendre; the slice rows are issue 15's path, its
# first at that issue's defaults).
settings=("default k4 o2 32/3|--k 4 --offset 2 --nphi-env 32 --nphi-key 3 --visibility legendre"
          "default, wedge tables|--k 4 --offset 2 --nphi-env 32 --nphi-key 3 --visibility wedge"
          "k8 o4 64/8|--k 8 --offset 4 --nphi-env 64 --nphi-key 8 --visibility legendre"
          "k16 o8 128/16|--k 16 --offset 8 --nphi-env 128 --nphi-key 16 --visibility legendre"
          "slice k3 o5 12/3|--k 3 --offset 5 --nphi-env 12 --nphi-key 3 --visibility slice"
          "slice k16 o8 128/16|--k 16 --offset 8 --nphi-env 128 --nphi-key 16 --visibility slice")


echo "| scene (${N}x${N}) | lights | settings | mean abs | RMSE | p99 abs | max abs | non-finite | cpu s | truth s |"
echo "|---|---|---|---|---|---|---|---|---|---|"
for sc in "${scenes[@]}"; do
  IFS='|' read -r name hf extra <<<"$sc"
  for li in "${lightings[@]}"; do
    IFS='|' read -r lname LIGHT <<<"$li"
    truth=$C/truth-$name$N-$lname.pfm
    # shellcheck disable=SC2086
    bench_truth "$HFS" "$truth" --height "$hf" $extra $LIGHT
    tsec=$(bench_seconds "${truth%.pfm}.log")
    for st in "${settings[@]}"; do
        IFS='|' read -r label flags <<<"$st"
        out=$C/cpu-$name$N.pfm
        "$HFS" render --height "$hf" $extra $LIGHT --backend cpu --subsample 1 $flags --pfm "$out" 2>"$C/cpu.log"
        csec=$(bench_seconds "$C/cpu.log")
        m=$("$HFS" compare --height "$hf" $extra $LIGHT "$out" "$truth")
        read -r _ mean _ rmse _ p99 _ mx _ nf _ <<<"$m"
        echo "| $name | $lname | $label | $mean | $rmse | $p99 | $mx | $nf | $csec | $tsec |"
    done
  done
done
