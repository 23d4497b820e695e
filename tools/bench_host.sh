#!/usr/bin/env bash
# The host's part of a cold frame (issue 37 item 3: "no per-frame work on
# the host that scales with the field"), two builds side by side: each
# round runs tests/gles_bench --cold (a terrain change every frame: the
# heights split and uploaded, the bounds built, the image read back) on
# each build in turn, and takes the medians over its frames of the frame's
# wall, the sum of its passes' times, the upload and the read-back.  The
# host part is wall - passes (the work no pass's timer holds: what the GPU
# waits for); the read-back and upload rows hold host work too (their
# conversions run inside their timers).  Prints a Markdown table of the
# medians over ROUNDS rounds.
# usage: tools/bench_host.sh BUILD_A BUILD_B [SIZE] [ROUNDS] [FRAMES]
#        (defaults 1024 3 3; a build needs the gles_bench target)
set -euo pipefail
cd "$(dirname "$0")/.."
# shellcheck source=tools/bench_lib.sh
. tools/bench_lib.sh
A=${1:?usage: bench_host.sh BUILD_A BUILD_B [SIZE] [ROUNDS] [FRAMES]}
B=${2:?usage: bench_host.sh BUILD_A BUILD_B [SIZE] [ROUNDS] [FRAMES]}
N=${3:-1024}
R=${4:-3}
F=${5:-3}
C=$(mktemp -d)
trap 'rm -rf "$C"' EXIT
for _ in $(seq "$R"); do
    for side in A B; do
        dir=$A
        [ "$side" = B ] && dir=$B
        "$dir/tests/gles_bench" --size "$N" --lights both --path slice --frames "$F" --cold |
            awk -v s="$side" '$1 == "upload" {u = $2} $1 == "readback" {r = $2}
                              $1 == "sum" {p = $2} $1 == "frame" && $2 == "wall" {w = $3}
                              END {print s, w, p, w - p, u, r}' >>"$C/rows"
    done
done
col() { # SIDE FIELD: the median over the rounds
    awk -v s="$1" -v f="$2" '$1 == s {print $f}' "$C/rows" | bench_median
}
echo "| ${N}² cold frame (medians of $R rounds) | A | B | B / A |"
echo "|---|---|---|---|"
for row in "frame wall ms|2" "passes ms|3" "host part (wall - passes) ms|4" "upload ms|5" \
           "read-back ms|6"; do
    IFS='|' read -r name f <<<"$row"
    a=$(col A "$f") b=$(col B "$f")
    awk -v n="$name" -v a="$a" -v b="$b" \
        'BEGIN {printf "| %s | %.1f | %.1f | %.3f |\n", n, a, b, (a != 0) ? b / a : 0}'
done
