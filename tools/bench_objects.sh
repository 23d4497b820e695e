#!/usr/bin/env bash
# What objects cost a 3-D view (issue 19, runtime/core/objects.h): the wall time
# of `hfshade render --time FRAMES` (FRAMES + 1 frames, GLES, each frame
# rerunning every pass and lighting the objects again) of the demo DEM's
# view with and without data/demo-objects.txt (9 pins, 3 boxes: 1500 lit
# vertices), with the key light and without it (then no point query: the
# environment's horizon march alone), alternating ROUNDS times.  Prints
# the median extra milliseconds per frame.
# usage: tools/bench_objects.sh [BUILD_DIR] [ROUNDS] [FRAMES]   (defaults build 3 10)
set -euo pipefail
cd "$(dirname "$0")/.."
B=${1:-build}
R=${2:-3}
F=${3:-10}
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
BASE="--height data/jacksboro.png --dx 83 --zscale 2 --albedo 0.35"
BASE="$BASE --env-sh 1.1,0,0.6,0,0,0,0,0,0,0,0,0,0,0,0,0"
V="--view perspective --camera 290,35,8000,40,16300,10400,1100 --view-size 640x384"
wall() { # ARGS... -> seconds
    /usr/bin/time -f %e -o "$T/t" "$B/tools/hfshade" render "$@" --time "$F" -o "$T/o.png" \
        >/dev/null
    cat "$T/t"
}
median() { sort -g | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }
echo "| lights | objects: extra ms per view frame (median of $R rounds, $((F + 1)) frames each) |"
echo "|---|---|"
for light in "sky + key 336,10,2,6000|--key 336,10,2,6000" "sky alone|"; do
    IFS='|' read -r name key <<<"$light"
    : >"$T/d"
    for ((i = 0; i < R; ++i)); do
        # shellcheck disable=SC2086
        a=$(wall $BASE $key $V)
        # shellcheck disable=SC2086
        b=$(wall $BASE $key $V --objects data/demo-objects.txt)
        echo "($b - $a) * 1000 / ($F + 1)" | bc -l >>"$T/d"
    done
    printf '| %s | %.0f |\n' "$name" "$(median <"$T/d")"
done
