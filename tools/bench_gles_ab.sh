#!/usr/bin/env bash
# GLES frame times of two builds side by side (e.g. before and after a
# refactoring): each configuration is timed ROUNDS times, the two builds
# alternating within each round (so drift on a shared machine hits both),
# every frame running every pass (hfshade render --time: caches
# invalidated).  Prints the median frame ms of each build and the median of
# the per-round ratios B / A, as a Markdown table.
# usage: tools/bench_gles_ab.sh BUILD_A BUILD_B [ROUNDS] [FRAMES]   (defaults 5 5)
# AB_FLAGS_A / AB_FLAGS_B: extra render flags for each side, e.g. the same
# build twice with AB_FLAGS_B="--visibility slice" compares two paths.
# AB_SKY: the environment flags (default a uniform SH sky of radiance 1).
# AB_SUN: the key light's flags (default a 2-degree sun 15 degrees up;
# e.g. AB_SUN="--key 336,4,0.25,1500" for a small low sun).
# AB_FIELD: a height file to time instead of the fractals (two rows: the
# sky and the sun, the sun alone; its scene flags in AB_FLAGS_A/B).
set -euo pipefail
cd "$(dirname "$0")/.."
# shellcheck source=tools/bench_lib.sh
. tools/bench_lib.sh
A=${1:?usage: bench_gles_ab.sh BUILD_A BUILD_B [ROUNDS] [FRAMES]}
B=${2:?usage: bench_gles_ab.sh BUILD_A BUILD_B [ROUNDS] [FRAMES]}
R=${3:-5}
F=${4:-5}
C=$(mktemp -d)
trap 'rm -rf "$C"' EXIT
SKY=${AB_SKY:-"--env-sh 3.5449077,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0"}
SUN=${AB_SUN:-"--key 336,15,2,1500"}
LOCAL="--local 40,40,30,4,2000 --local 90,30,25,3,1500"
"$B/tools/hfgen" fractal --size 256x256 -o "$C/f256.pfm"
"$B/tools/hfgen" fractal --size 512x512 -o "$C/f512.pfm"
echo "| scene | A frame ms | B frame ms | B / A (median of $R rounds) |"
echo "|---|---|---|---|"
cfgs=("256² env+key sub 2|$C/f256.pfm|$SKY $SUN --subsample 2"
      "256² env sub 1 fp32|$C/f256.pfm|$SKY --subsample 1 --precision fp32"
      "256² env+key+2 local sub 2|$C/f256.pfm|$SKY $SUN $LOCAL --subsample 2"
      "512² env+key sub 2|$C/f512.pfm|$SKY $SUN --subsample 2")
if [ -n "${AB_FIELD:-}" ]; then
    cfgs=("$(basename "$AB_FIELD") env+key sub 2|$AB_FIELD|$SKY $SUN --subsample 2"
          "$(basename "$AB_FIELD") key sub 2|$AB_FIELD|$SUN --subsample 2")
fi
for cfg in "${cfgs[@]}"; do
    IFS='|' read -r name field args <<<"$cfg"
    # shellcheck disable=SC2086 # the scene's flags are words
    read -r a b r _ <<<"$(bench_ab "$A" "$B" "$R" "$F" "$C" "${AB_FLAGS_A:-}" "${AB_FLAGS_B:-}" \
        --height "$field" $args --backend gles)"
    printf '| %s | %.1f | %.1f | %.3f |\n' "$name" "$a" "$b" "$r"
done
