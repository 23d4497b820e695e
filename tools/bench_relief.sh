#!/usr/bin/env bash
# The sky at any relief (issue 36; DESIGN.md "Split horizons", "At any
# relief"): a 32x32 `hfgen fractal` under a uniform SH sky (albedo 0.8),
# then under a key light (a 2-degree sun 15 degrees up) alone, with its
# relief scaled, each backend at subsample 1, 2 and 4 against the ground
# truth of the same relief.  Two sweeps:
#   dx 1, zscale 1e3 .. 1e6 (relief about 1.6e3 .. 1.6e6 texels: past
#     2^14 the grids' occluder heights need their unit, hfs_split_h_unit);
#   dx 1e-9, zscale 1e6 .. 1e12 (slopes 1e15 .. 1e21: the validated
#     ranges' corner).
# Columns: mean / max abs error of the unshadowed maximum (`hfshade
# compare`).  Each BUILD is LABEL=DIR as in bench_umbra.sh; the truth comes
# from the last (the truth's receivers lift as SPEC says only where the
# lift is above the height's resolution since session 38: the newest).
#   tools/bench_relief.sh before=/tmp/old/build now=build
set -euo pipefail
cd "$(dirname "$0")/.."
# shellcheck source=tools/bench_lib.sh
. tools/bench_lib.sh
bench_builds "$@"
last=${BUILDS[${#BUILDS[@]} - 1]}
HT="${last#*=}/tools/hfshade"
W=$(mktemp -d)
trap 'rm -rf "$W"' EXIT
"$GEN" fractal --size 32x32 -o "$W/f32.pfm"
for LIGHT in "--env-sh 3.5449077,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0 --albedo 0.8" \
    "--key 336,15,2,300 --albedo 0.8"; do
echo
echo "${LIGHT%% *}:"
echo
echo "| dx | zscale | build | cpu sub 1 | cpu sub 2 | cpu sub 4 | gles sub 1 | gles sub 2 | gles sub 4 |"
echo "|---|---|---|---|---|---|---|---|---|"
for dz in "1 1e3" "1 1e4" "1 1e5" "1 1e6" "1e-9 1e6" "1e-9 1e8" "1e-9 1e9" "1e-9 1e10" "1e-9 1e11" "1e-9 1e12"; do
    read -r dx z <<<"$dz"
    # shellcheck disable=SC2086 # LIGHT's flags are words
    A=(--height "$W/f32.pfm" --dx "$dx" --zscale "$z" $LIGHT)
    "$HT" render "${A[@]}" --backend truth --pfm "$W/truth.pfm" -o "$W/x.png" --quiet
    for b in "${BUILDS[@]}"; do
        label=${b%%=*} dir=${b#*=}
        row="| $dx | $z | $label |"
        for be in cpu gles; do
            for sub in 1 2 4; do
                "$dir/tools/hfshade" render "${A[@]}" --backend "$be" --subsample "$sub" \
                    --pfm "$W/r.pfm" -o "$W/x.png" --quiet
                read -r _ mean _ _ _ _ _ max _ <<<"$("$HT" compare "${A[@]}" "$W/r.pfm" "$W/truth.pfm")"
                row="$row $mean / $max |"
            done
        done
        echo "$row"
    done
done
done
