#!/usr/bin/env bash
# Sharp suns on the 2x2 grid (issue 36, deliverable 2): a synthetic HDR sky
# (`hfgen sky`: a 0.5-degree sun holding 80% of the energy, at 5, 10, 20
# and 40 degrees up) over the 64x64 fractal (relief 0.25), against the
# truth of the map (truth-env = map): the GLES path at subsample 2 (the
# default) and 1, with the map shaded from itself (env-lights off) and
# with the sun as a key light (env-lights auto).  Columns: mean and p99
# error (fractions of the unshadowed maximum), the 2x2 p99 over subsample
# 1's, and the frame's median time (ms, --time 3, this machine).  Each
# BUILD is LABEL=DIR (default now=build); two compare side by side:
#   tools/bench_sharp.sh before=/tmp/old/build now=build
set -euo pipefail
cd "$(dirname "$0")/.."
# shellcheck source=tools/bench_lib.sh
. tools/bench_lib.sh
bench_builds "$@"
"$GEN" fractal --size 64x64 --relief 0.25 -o "$C/sharp-fractal64.pfm"
HF=$C/sharp-fractal64.pfm

echo "| sun elevation | env-lights | build | sub 2 mean | sub 2 p99 | sub 1 mean | sub 1 p99 | p99 sub 2 / sub 1 | frame ms sub 2 / sub 1 |"
echo "|---|---|---|---|---|---|---|---|---|"
for el in 5 10 20 40; do
    sky=$C/sharp-sky-$el.pfm
    "$GEN" sky --size 1024x512 --sun "135,$el" -o "$sky"
    truth=$C/sharp-truth-$el.pfm
    bench_truth "$HFS0" "$truth" --height "$HF" --env-map "$sky"
    for lights in off auto; do
        for b in "${BUILDS[@]}"; do
            label=${b%%=*} dir=${b#*=}
            declare -A mean p99 ms
            for sub in 2 1; do
                a=(--height "$HF" --env-map "$sky" --env-lights "$lights" --subsample "$sub")
                "$dir/tools/hfshade" render "${a[@]}" --pfm "$C/sharp.pfm" -o "$C/sharp.png" --quiet
                read -r _ m _ _ _ p _ <<<"$("$HFS0" compare --height "$HF" --env-map "$sky" \
                    "$C/sharp.pfm" "$truth")"
                mean[$sub]=$m p99[$sub]=$p ms[$sub]=$(bench_frame_ms "$dir/tools/hfshade" "${a[@]}")
            done
            ratio=$(awk -v a="${p99[2]}" -v b="${p99[1]}" 'BEGIN { printf "%.2f", a / b }')
            echo "| $el | $lights | $label | ${mean[2]} | ${p99[2]} | ${mean[1]} | ${p99[1]} | $ratio | ${ms[2]} / ${ms[1]} |"
        done
    done
done
