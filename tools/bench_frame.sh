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
A=${1:?usage: bench_frame.sh BASE_BUILD NOW_BUILD [ROUNDS] [FRAMES]}
B=${2:?usage: bench_frame.sh BASE_BUILD NOW_BUILD [ROUNDS] [FRAMES]}
R=${3:-5}
F=${4:-5}
C=$(mktemp -d)
trap 'rm -rf "$C"' EXIT
SKY="--env-sh 3.5449077,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0"
MAP="--env-map data/courtyard.exr"
SUN="--key 336,15,2,1500"
# frame BUILD ARGS... -> "median_frame_ms texture_MiB" of F frames
frame() {
    local b=$1
    shift
    "$b/tools/hfshade" render "$@" --time "$F" --pfm "$C/out.pfm" |
        awk '$1 == "frame" {f = $2} /^texture memory/ {m = $3} END {print f, m}'
}
median() { sort -g | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }
for n in 256 512; do
    "$B/tools/hfgen" fractal --size ${n}x${n} -o "$C/f$n.pfm"
done
echo "| frame | base ms | now ms | now / base (median of $R rounds) | goal | met |"
echo "|---|---|---|---|---|---|"
: >"$C/mem"
for cfg in "256² SH sky + key|256|$SKY|0.70" "256² env map + key|256|$MAP|0.70" \
           "512² SH sky + key|512|$SKY|0.55" "512² env map + key|512|$MAP|0.55"; do
    IFS='|' read -r name n env goal <<<"$cfg"
    : >"$C/a" && : >"$C/b" && : >"$C/r"
    for ((i = 0; i < R; ++i)); do
        # shellcheck disable=SC2086
        read -r a ma <<<"$(frame "$A" --height "$C/f$n.pfm" $env $SUN --backend gles)"
        # shellcheck disable=SC2086
        read -r b mb <<<"$(frame "$B" --height "$C/f$n.pfm" $env $SUN --backend gles)"
        echo "$a" >>"$C/a"
        echo "$b" >>"$C/b"
        awk -v a="$a" -v b="$b" 'BEGIN {print b / a}' >>"$C/r"
    done
    [ "$n" = 512 ] && echo "$name|$ma|$mb" >>"$C/mem"
    r=$(median <"$C/r")
    met=$(awk -v r="$r" -v g="$goal" 'BEGIN {print (r <= g) ? "yes" : "no"}')
    printf '| %s | %.1f | %.1f | %.3f | <= %s | %s |\n' "$name" "$(median <"$C/a")" \
        "$(median <"$C/b")" "$r" "$goal" "$met"
done
echo
echo "| texture memory | base MiB | now MiB | goal | met |"
echo "|---|---|---|---|---|"
while IFS='|' read -r name ma mb; do
    met=$(awk -v m="$mb" 'BEGIN {print (m <= 12) ? "yes" : "no"}')
    echo "| $name | $ma | $mb | <= 12 | $met |"
done <"$C/mem"
