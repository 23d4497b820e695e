#!/usr/bin/env bash
# Long shadows of narrow features (issue 36): how much of the truth's umbra
# each build renders lit, and the error against the truth.
#   towers  one block on a flat 1024x256 field (hfgen tower --block W,H),
#           a sun of radius 0.25 degrees from azimuth 180 (the shadow runs
#           down the field): 40x30 at 4 degrees, 10x20 at 8, 4x10 at 10,
#           2x6 at 15;
#   boxes   random boxes 2-40 texels wide, 5-40 tall on a flat 256x256
#           field (hfgen boxes), suns at 3, 5, 10 and 20 degrees;
#   city    hfgen city at 256x256 against the terrain scenes (cones, the
#           fractal, the DEM window, and the rough ones: the relief-1
#           fractal, the Hurst-0.25 and Hurst-0.8 fields at 64x64) under
#           the courtyard sky's order-4 projection and a 2-degree sun 5
#           degrees up.
# UMBRA_GROUPS (default "towers boxes city") runs only the groups named.
# Columns: `hfshade compare`'s umbra_lit (texels of the truth's umbra, below
# 1% of their unshadowed value, rendered at half of it or more), its mean
# and p99 error (fractions of the unshadowed maximum), and the render's
# wall time with --time 3 (per-frame median, this machine).  Each BUILD is
# LABEL=DIR (default now=build); give two to compare side by side, e.g.
#   tools/bench_umbra.sh before=/tmp/old/build now=build
# Truth renders are cached in the first build's bench-cache.
set -euo pipefail
cd "$(dirname "$0")/.."
# shellcheck source=tools/bench_lib.sh
. tools/bench_lib.sh
bench_builds "$@"

# row NAME HEIGHT LIGHT...: one table row per build and backend.
row() {
    local name=$1 hf=$2
    shift 2
    local truth=$C/umbra-truth-$name.pfm
    bench_truth "$HFS0" "$truth" --height "$hf" "$@"
    for b in "${BUILDS[@]}"; do
        local label=${b%%=*} dir=${b#*=}
        for be in "cpu|--backend cpu --subsample 1" "gles sub 2|--backend gles" "gles sub 1|--backend gles --subsample 1"; do
            IFS='|' read -r bname bflags <<<"$be"
            local out=$C/umbra-$name.pfm
            # shellcheck disable=SC2086
            "$dir/tools/hfshade" render --height "$hf" "$@" $bflags --pfm "$out" -o "$C/umbra.png" --quiet
            local m ms
            m=$("$HFS0" compare --height "$hf" "$@" "$out" "$truth")
            # shellcheck disable=SC2086
            ms=$(bench_frame_ms "$dir/tools/hfshade" --height "$hf" "$@" $bflags)
            local mean p99 lit
            read -r _ mean _ _ _ p99 _ _ _ _ _ _ _ lit <<<"$m"
            echo "| $name | $label | $bname | $lit | $mean | $p99 | ${ms:--} |"
        done
    done
}

WANT=" ${UMBRA_GROUPS:-towers boxes city} "
echo "| scene | build | backend | umbra lit / umbra | mean abs | p99 abs | frame ms |"
echo "|---|---|---|---|---|---|---|"
for t in "40,30,4" "10,20,8" "4,10,10" "2,6,15"; do
    [[ $WANT == *" towers "* ]] || break
    IFS=, read -r bw bh el <<<"$t"
    "$GEN" tower --size 1024x256 --block "$bw,$bh" -o "$C/tower-$bw-$bh.pfm"
    row "tower${bw}x${bh}-sun$el" "$C/tower-$bw-$bh.pfm" --key "180,$el,0.25,1"
done
[[ $WANT == *" boxes "* ]] && "$GEN" boxes --size 256x256 -o "$C/boxes256.pfm"
for el in 3 5 10 20; do
    [[ $WANT == *" boxes "* ]] || break
    row "boxes-sun$el" "$C/boxes256.pfm" --key "$((40 + 7 * el)),$el,0.25,1"
done
[[ $WANT == *" city "* ]] || exit 0
bench_rough_scenes "$GEN" "$C" 256
"$GEN" city --size 256x256 -o "$C/city256.pfm"
scenes+=("city|$C/city256.pfm|--dx 1")
for sc in "${scenes[@]}"; do
    IFS='|' read -r name hf extra <<<"$sc"
    # shellcheck disable=SC2086
    row "$name-sky+sun5" "$hf" $extra --env-map data/courtyard.exr --truth-env sh --env-shade sh \
        --key 336,5,2,1500
done
