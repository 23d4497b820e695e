#!/usr/bin/env bash
# bench_envmap.sh — the renderers against the truth of the environment map
# itself (issue 17 part 3, DESIGN.md "Ground truth of an environment map").
#
# usage: tools/bench_envmap.sh BUILD_DIR SIZE [MAP ...] [-- HFSHADE FLAGS ...]
#
# On the fractal and the DEM of the benchmark scenes (tools/bench_lib.sh
# bench_scenes) at SIZE x SIZE, for data/courtyard.exr and every MAP given:
#   - "truth of the SH": the ground truth of the map's order-4 SH projection
#     (what the truth measured before it integrated maps): how much of the
#     map no SH-based renderer can reach;
#   - "cpu", "gles": the CPU reference and the GLES renderer (defaults),
#     with the flags after "--" (e.g. --env-lights auto) added;
# each against the truth of the map itself (cached in BUILD_DIR/bench-cache,
# keyed by its arguments), by `hfshade compare` (SPEC metrics: absolute
# errors over the largest unshadowed value of the scene's lighting without
# the extra flags, so every row of a scene shares one normalizer); the last
# column is the mean abs error against the truth of the SH instead.  Prints
# a Markdown table; each truth's wall time is in its log beside it.
# BENCH_ENV_BASE: scene flags added to every row, the truths and the
# normalizer included (e.g. "--specular 0.3 --gloss 32": a glossy surface,
# issue 36); the truths' cache names carry them.
set -euo pipefail
cd "$(dirname "$0")/.."
# shellcheck source=tools/bench_lib.sh
. tools/bench_lib.sh
B=${1:?usage: bench_envmap.sh BUILD_DIR SIZE [MAP ...] [-- FLAGS ...]}
N=${2:?usage: bench_envmap.sh BUILD_DIR SIZE [MAP ...] [-- FLAGS ...]}
shift 2
maps=(data/courtyard.exr)
while [ $# -gt 0 ] && [ "$1" != "--" ]; do
    maps+=("$1")
    shift
done
[ $# -gt 0 ] && shift
extra=("$@")
HFS=$B/tools/hfshade
C=$B/bench-cache
mkdir -p "$C"
bench_scenes "$B/tools/hfgen" "$C" "$N" >/dev/null
echo "| map | scene (${N}x${N}) | renderer | mean abs | p99 abs | max abs | mean abs vs the truth of the SH |"
echo "|---|---|---|---|---|---|---|"
for map in "${maps[@]}"; do
    [ -r "$map" ] || { echo "bench_envmap: $map: cannot read" >&2; exit 1; }
    tag=$(basename "${map%.*}")
    for sc in "${scenes[@]}"; do
        IFS='|' read -r name hf flags <<<"$sc"
        [ "$name" = cones ] && continue
        # shellcheck disable=SC2206 # flags are words
        # shellcheck disable=SC2206 # BENCH_ENV_BASE is words
        base=(--height "$hf" $flags --env-map "$map" ${BENCH_ENV_BASE:-})
        btag=$(printf '%s' "${BENCH_ENV_BASE:-}" | tr -c 'A-Za-z0-9.' '_')
        truth=$C/envtruth-$name$N-$tag$btag.pfm
        bench_truth "$HFS" "$truth" "${base[@]}" --truth-azimuths 720
        shtruth=$C/envshtruth-$name$N-$tag$btag.pfm
        bench_truth "$HFS" "$shtruth" "${base[@]}" --truth-azimuths 720 --truth-env sh
        row() { # LABEL RESULT.pfm
            local m vs
            m=$("$HFS" compare "${base[@]}" "$2" "$truth")
            read -r _ mean _ _ _ p99 _ mx _ <<<"$m"
            vs=-
            if [ "$2" != "$shtruth" ]; then
                read -r _ vs _ <<<"$("$HFS" compare "${base[@]}" "$2" "$shtruth")"
            fi
            echo "| $tag | $name | $1 | $mean | $p99 | $mx | $vs |"
        }
        row "truth of the SH" "$shtruth"
        for be in cpu gles; do
            sub=() # the CPU reference at full resolution (issue 36 item 5: it honours --subsample)
            [ "$be" = cpu ] && sub=(--subsample 1)
            "$HFS" render "${base[@]}" "${extra[@]}" --backend $be "${sub[@]}" --pfm "$C/envmap-$be.pfm" --quiet
            row "$be${extra[*]:+ ${extra[*]}}" "$C/envmap-$be.pfm"
        done
    done
done
