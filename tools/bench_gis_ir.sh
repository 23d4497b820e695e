#!/usr/bin/env bash
# Two builds' GIS commands by their instructions (valgrind's callgrind):
# counts that do not move with the machine's load, where the wall clock
# of a shared 2-core machine moves by 10-15% between runs of one binary
# (tools/bench_gis_ab.sh times the same commands).  `hfshade horizon` (16
# azimuths), `svf` and `insolation --beam-only` (a June day in 30-minute
# steps), all `--method sweep`, on DEM (jacksboro, the default, or
# fractal:N, as bench_gdal.sh makes them); each build's instructions, B /
# A, and the bytes of the 16 horizon files.  Needs gdal-bin and valgrind.
# usage: tools/bench_gis_ir.sh BUILD_A BUILD_B [DEM]
set -euo pipefail
cd "$(dirname "$0")/.."
A=$(cd "${1:?usage: bench_gis_ir.sh BUILD_A BUILD_B [DEM]}" && pwd)
B=$(cd "${2:?usage: bench_gis_ir.sh BUILD_A BUILD_B [DEM]}" && pwd)
DEM=${3:-jacksboro}
C=$(mktemp -d)
trap 'rm -rf "$C"' EXIT
. tools/bench_gdal.sh
bench_gdal_need valgrind
bench_dem_utm "$(pwd)" "$B" "$DEM" "$C/utm.tif" || exit 2
DAY="--from 2026-06-21T00:00 --to 2026-06-22T00:00 --timezone -05:00 --step 30 --linke 3"
# ir BUILD ARGS...: the instructions of one run (callgrind's total)
ir() {
    local b=$1
    shift
    valgrind --tool=callgrind --callgrind-out-file=/dev/null "$b/tools/hfshade" "$@" --quiet 2>&1 |
        sed -n 's/.*Collected : \([0-9]*\).*/\1/p'
}
echo "| command | A (instructions) | B | B / A |"
echo "|---|---|---|---|"
for c in horizon svf beam; do
    for k in a b; do
        b=$A
        [ "$k" = b ] && b=$B
        mkdir -p "$C/$k"
        # shellcheck disable=SC2086 # DAY's flags are words
        case $c in
        horizon) n=$(ir "$b" horizon "$C/utm.tif" --step 22.5 --method sweep -o "$C/$k/hor") ;;
        svf) n=$(ir "$b" svf "$C/utm.tif" --method sweep -o "$C/$k/svf.tif") ;;
        beam) n=$(ir "$b" insolation "$C/utm.tif" $DAY --method sweep --beam-only -o "$C/$k/b.tif") ;;
        esac
        eval "n_$k=$n"
    done
    # shellcheck disable=SC2154 # n_a, n_b set by eval above
    awk -v c="$c" -v a="$n_a" -v b="$n_b" \
        'BEGIN {printf "| %s | %.0f M | %.0f M | %.3f |\n", c, a / 1e6, b / 1e6, b / a}'
done
echo "horizon files: A $(cat "$C"/a/hor_*.tif | wc -c) bytes, B $(cat "$C"/b/hor_*.tif | wc -c) bytes"
