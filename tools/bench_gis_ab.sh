#!/usr/bin/env bash
# Two builds' GIS commands side by side (the ratio of a change, not the
# peers: tools/bench_gis.sh has those): `hfshade horizon` (16 azimuths),
# `svf`, `insolation` (a June day in 30-minute steps) and the same day's
# `insolation --beam-only` (the beam alone, r.sun's beam_rad) on data/jacksboro.png
# in UTM 16N with 83 m cells (as bench_gis.sh places it), GLES, the whole
# DEM searched.  Rounds alternate A, B, A, B...; each command's wall-clock
# median of ROUNDS runs per build, and B / A.  Needs gdal-bin (gdal_translate).
# GIS_AB_FLAGS: more flags for every command of both builds (e.g.
# "--method sweep").
# DEM: jacksboro (the default) or fractal:N (an hfgen fractal of N x N,
# 30 m cells, as bench_gis.sh makes it with BUILD_B's hfgen).
# usage: tools/bench_gis_ab.sh BUILD_A BUILD_B [ROUNDS] [DEM]   (default 3)
set -euo pipefail
cd "$(dirname "$0")/.."
A=$(cd "${1:?usage: bench_gis_ab.sh BUILD_A BUILD_B [ROUNDS]}" && pwd)
B=$(cd "${2:?usage: bench_gis_ab.sh BUILD_A BUILD_B [ROUNDS]}" && pwd)
ROUNDS=${3:-3}
DEM=${4:-jacksboro}
C=$(mktemp -d)
trap 'rm -rf "$C"' EXIT
. tools/bench_gdal.sh
bench_dem_utm "$(pwd)" "$B" "$DEM" "$C/utm.tif" || exit 2
DAY="--from 2026-06-21T00:00 --to 2026-06-22T00:00 --timezone -05:00 --step 30 --linke 3"
now() { date +%s.%N; }
# run NAME BUILD ARGS...: appends the wall seconds of one run to NAME.t
run() {
    local name=$1 b=$2 t0
    shift 2
    t0=$(now)
    # shellcheck disable=SC2086 # the flags are words
    "$b/tools/hfshade" "$@" ${GIS_AB_FLAGS:-} --quiet >/dev/null
    awk -v a="$t0" -v b="$(now)" 'BEGIN {printf "%.3f\n", b - a}' >>"$C/$name.t"
}
mkdir -p "$C/a" "$C/b"
for _ in $(seq "$ROUNDS"); do
    for k in a b; do
        b=$A
        [ "$k" = b ] && b=$B
        run "horizon_$k" "$b" horizon "$C/utm.tif" --step 22.5 -o "$C/$k/hor"
        run "svf_$k" "$b" svf "$C/utm.tif" -o "$C/$k/svf.tif"
        # shellcheck disable=SC2086 # DAY's flags are words
        run "insolation_$k" "$b" insolation "$C/utm.tif" $DAY -o "$C/$k/ins.tif"
        # shellcheck disable=SC2086 # DAY's flags are words
        run "beam_$k" "$b" insolation "$C/utm.tif" $DAY --beam-only -o "$C/$k/beam.tif"
    done
done
median() { sort -n "$1" | awk '{v[NR] = $1} END {print NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }
echo "| command | A (s) | B (s) | B / A |"
echo "|---|---|---|---|"
for c in horizon svf insolation beam; do
    awk -v c="$c" -v a="$(median "$C/${c}_a.t")" -v b="$(median "$C/${c}_b.t")" \
        'BEGIN {printf "| %s | %.2f | %.2f | %.2f |\n", c, a, b, b / a}'
done
