#!/usr/bin/env bash
# What a bounce costs on the GLES path (issue 16): the frame with 0..3
# bounces at the defaults on the fractal under the demo's sky + sun, at
# 256^2 and 512^2, side by side in rounds (the bounce counts alternating
# within each round, so drift on a shared machine hits them all), every
# frame running every pass (hfshade render --time: caches invalidated).
# Prints, as a Markdown table, the median frame ms, the median bounce
# pass ms, the median per-round ratio of the frame to the direct frame
# (0 bounces), and the texture memory.
# usage: tools/bench_bounce_cost.sh [BUILD_DIR] [ROUNDS] [FRAMES]   (defaults build 5 5)
set -euo pipefail
cd "$(dirname "$0")/.."
B=${1:-build}
R=${2:-5}
F=${3:-5}
C=$(mktemp -d)
trap 'rm -rf "$C"' EXIT
median() { sort -g | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }
echo "| field | bounces | frame ms | bounce pass ms | frame / direct frame | texture MiB |"
echo "|---|---|---|---|---|---|"
for n in 256 512; do
    "$B/tools/hfgen" fractal --size ${n}x$n -o "$C/f.pfm"
    for ((i = 0; i < R; ++i)); do
        for b in 0 1 2 3; do
            "$B/tools/hfshade" render --height "$C/f.pfm" --env-map data/courtyard.exr \
                --key 336,15,2,1500 --bounces $b --time "$F" --pfm "$C/out.pfm" >"$C/t"
            awk '$1 == "frame" {print $2}' "$C/t" >>"$C/frame$b"
            awk '$1 == "bounce" {print $2}' "$C/t" >>"$C/pass$b"
            awk '$1 == "texture" {print $3}' "$C/t" >"$C/mem$b"
        done
        for b in 0 1 2 3; do
            awk -v a="$(sed -n "$((i + 1))p" "$C/frame0")" -v x="$(sed -n "$((i + 1))p" "$C/frame$b")" \
                'BEGIN {print x / a}' >>"$C/ratio$b"
        done
    done
    for b in 0 1 2 3; do
        pass=$( [ -s "$C/pass$b" ] && median <"$C/pass$b" || echo 0)
        printf '| %d² | %d | %.1f | %.1f | %.3f | %s |\n' "$n" "$b" "$(median <"$C/frame$b")" \
            "$pass" "$(median <"$C/ratio$b")" "$(cat "$C/mem$b")"
    done
    rm -f "$C"/frame* "$C"/pass* "$C"/ratio* "$C"/mem*
done
