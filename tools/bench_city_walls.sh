#!/usr/bin/env bash
# Where the city's error lies (issue 36 item 1; docs/benchmarks/long-shadows.md
# "Where the city's error lies"): an `hfgen city` field under the courtyard
# sky at order 4 (truth-env = sh, env-shade = sh: the sky alone, the city's
# excess over the terrains), rendered by GLES at subsample 1 and 2 and the
# CPU reference at the defaults, each against the exact truth (cached in
# BUILD/bench-cache), then its error by texel class
# (tools/pfm_wall_classes.py: flat ground, a step's foot, its top).
# usage: tools/bench_city_walls.sh [BUILD] [SIZE] [FLAGS...]   (defaults: build 128)
# FLAGS go to the three renders, not the truth (e.g. --nphi-env 24).
set -euo pipefail
cd "$(dirname "$0")/.."
# shellcheck source=tools/bench_lib.sh
. tools/bench_lib.sh
B=${1:-build}
N=${2:-128}
shift 2 || true
FLAGS=("$@")
HFS=$B/tools/hfshade
C=$B/bench-cache
mkdir -p "$C"
"$B/tools/hfgen" city --size "${N}x${N}" -o "$C/city$N.pfm"
SCENE=(--height "$C/city$N.pfm" --dx 1 --env-map data/courtyard.exr --truth-env sh --env-shade sh)
truth=$C/truth-city$N-sky.pfm
bench_truth "$HFS" "$truth" "${SCENE[@]}"
for run in "gles|--subsample 1" "gles|--subsample 2" "cpu|--subsample 2"; do
    IFS='|' read -r be sub <<<"$run"
    out=$C/walls-city$N.pfm
    # shellcheck disable=SC2086 # the subsample flag is two words
    "$HFS" render "${SCENE[@]}" --backend "$be" $sub "${FLAGS[@]}" --pfm "$out" 2>/dev/null
    m=$("$HFS" compare "${SCENE[@]}" "$out" "$truth")
    read -r _ mean _ _ _ p99 _ _ _ _ _ norm _ <<<"$m"
    echo
    echo "$be $sub: mean $mean, p99 $p99 of the unshadowed maximum ($norm)"
    echo
    python3 tools/pfm_wall_classes.py "$out" "$truth" "$C/city$N.pfm" "$norm"
done
