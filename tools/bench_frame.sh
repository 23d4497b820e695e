#!/usr/bin/env bash
# The frames of issue 37 ("the frame at the cost of its fetches") against a
# base build, side by side: each configuration timed ROUNDS times, the two
# builds alternating within each round (drift on a shared machine hits
# both), every frame running every pass (hfshade render --time: caches
# invalidated).  Prints, as a Markdown table, each build's median frame
# (ms), the median of the per-round ratios NOW / BASE, the issue's goal for
# that ratio and whether it is met; then both builds' texture memory at
# 512² against the issue's 12 MiB.
# usage: tools/bench_frame.sh BASE_BUILD NOW_BUILD [ROUNDS] [FRAMES]   (defaults 5 5)
#   BASE_BUILD: a build of 04e3019, the issue's base, e.g.
#     git worktree add /tmp/base 04e3019 && cmake -S /tmp/base -B /tmp/base/build &&
#     cmake --build /tmp/base/build -j2 --target hfshade hfgen
# Scenes: `hfgen fractal` (relief 0.25) at 256² and 512², a uniform SH sky
# of radiance 1 or data/courtyard.exr, and a 2-degree sun 15 degrees up.
set -euo pipefail
cd "$(dirname "$0")/.."
# shellcheck source=tools/bench_lib.sh
. tools/bench_lib.sh
A=${1:?usage: bench_frame.sh BASE_BUILD NOW_BUILD [ROUNDS] [FRAMES]}
B=${2:?usage: bench_frame.sh BASE_BUILD NOW_BUILD [ROUNDS] [FRAMES]}
R=${3:-5}
F=${4:-5}
C=$(mktemp -d)
trap 'rm -rf "$C"' EXIT
SKY="--env-sh 3.5449077,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0"
MAP="--env-map data/courtyard.exr"
SUN="--key 336,15,2,1500"
for n in 256 512; do
    "$B/tools/hfgen" fractal --size ${n}x${n} -o "$C/f$n.pfm"
done
echo "| frame | base ms | now ms | now / base (median of $R rounds) | goal | met |"
echo "|---|---|---|---|---|---|"
: >"$C/mem"
for cfg in "256² SH sky + key|256|$SKY|0.70" "256² env map + key|256|$MAP|0.70" \
           "512² SH sky + key|512|$SKY|0.55" "512² env map + key|512|$MAP|0.55"; do
    IFS='|' read -r name n env goal <<<"$cfg"
    # shellcheck disable=SC2086 # the scene's flags are words
    read -r a b r ma mb <<<"$(bench_ab "$A" "$B" "$R" "$F" "$C" "" "" --height "$C/f$n.pfm" \
        $env $SUN --backend gles)"
    [ "$n" = 512 ] && echo "$name|$ma|$mb" >>"$C/mem"
    met=$(awk -v r="$r" -v g="$goal" 'BEGIN {print (r <= g) ? "yes" : "no"}')
    printf '| %s | %.1f | %.1f | %.3f | <= %s | %s |\n' "$name" "$a" "$b" "$r" "$goal" "$met"
done
echo
echo "| texture memory | base MiB | now MiB | goal | met |"
echo "|---|---|---|---|---|"
while IFS='|' read -r name ma mb; do
    met=$(awk -v m="$mb" 'BEGIN {print (m <= 12) ? "yes" : "no"}')
    echo "| $name | $ma | $mb | <= 12 | $met |"
done <"$C/mem"
