#!/usr/bin/env bash
# Texture memory of the default frame (issue 37 item 4), two builds side by
# side, from 256² to 2048²: `hfshade render --time 1` of an `hfgen fractal`
# field under a uniform SH sky or data/courtyard.exr (shaded from the map,
# the default) with a 2-degree sun 15 degrees up, GLES defaults; the
# renderer's own count (every texture it holds after the frame).
# usage: tools/bench_memory.sh BUILD_A BUILD_B [SIZES]   (default "256 512 1024 2048")
set -euo pipefail
cd "$(dirname "$0")/.."
A=${1:?usage: bench_memory.sh BUILD_A BUILD_B [SIZES]}
B=${2:?usage: bench_memory.sh BUILD_A BUILD_B [SIZES]}
SIZES=${3:-"256 512 1024 2048"}
C=$(mktemp -d)
trap 'rm -rf "$C"' EXIT
SKY="--env-sh 3.5449077,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0"
MAP="--env-map data/courtyard.exr"
SUN="--key 336,15,2,1500"
mib() { # BUILD ARGS...: the texture memory (MiB) the frame reports
    local b=$1
    shift
    "$b/tools/hfshade" render "$@" --time 1 --quiet -o "$C/o.png" 2>&1 |
        awk '$1 == "texture" && $2 == "memory:" {print $3}'
}
echo "| frame | A MiB | B MiB | B / A |"
echo "|---|---|---|---|"
for n in $SIZES; do
    "$B/tools/hfgen" fractal --size "${n}x${n}" -o "$C/f.pfm"
    for cfg in "SH sky + key|$SKY" "env map + key|$MAP"; do
        IFS='|' read -r name env <<<"$cfg"
        # shellcheck disable=SC2086 # the scene's flags are words
        a=$(mib "$A" --height "$C/f.pfm" $env $SUN) b=$(mib "$B" --height "$C/f.pfm" $env $SUN)
        awk -v n="${n}² $name" -v a="$a" -v b="$b" \
            'BEGIN {printf "| %s | %.2f | %.2f | %.3f |\n", n, a, b, b / a}'
    done
done
