#!/usr/bin/env bash
# insolation's sky-diffuse share S (band 2 over the clear sky's diffuse
# horizontal irradiation; docs/GIS.md "The sun") against the truth: the
# Jacksboro DEM in UTM 16N with 83 m cells (as tools/bench_gis.sh), one
# 30-minute step at noon, S of each run against the truth's exact
# horizons in 128 azimuths (`--backend truth --directions 128`), over the
# DEM less a 2-texel border: mean, p99 and max of |S - S_truth|.
# Rows: GLES and the CPU reference at the default 16 azimuths, the truth's
# own horizons in 16; with OLD_BUILD (a build of an earlier hfshade, e.g.
# a50c2d2, whose S was one render of an SH sky) its GLES and truth rows
# too.  Then a June day in 30-minute steps on GLES, timed (median of
# ROUNDS), with OLD_BUILD alternating.  Installs gdal-bin, python3-gdal
# and python3-numpy when missing.
# usage: tools/bench_sky_share.sh [BUILD] [OLD_BUILD] [ROUNDS]
#   e.g. tools/bench_sky_share.sh build /tmp/old-build 3
set -euo pipefail
cd "$(dirname "$0")/.."
B=${1:-build}
OLD=${2:-}
ROUNDS=${3:-3}
H="$(pwd)/$B/tools/hfshade"
O=${OLD:+$(cd "$OLD" && pwd)/tools/hfshade}
PY=/usr/bin/python3
. tools/bench_gdal.sh
bench_gdal_need
bench_jacksboro_workdir "$(pwd)"
NOON="--from 2026-06-21T12:00-05:00 --to 2026-06-21T12:30-05:00 --step 30"
DAY="--from 2026-06-21T05:00-05:00 --to 2026-06-21T21:00-05:00 --step 30"
"$H" insolation utm.tif $NOON -o truth128.tif --backend truth --directions 128 --quiet
"$H" insolation utm.tif $NOON -o truth16.tif --backend truth --quiet
"$H" insolation utm.tif $NOON -o gles.tif --quiet
"$H" insolation utm.tif $NOON -o cpu.tif --backend cpu --quiet
rows=(gles.tif cpu.tif truth16.tif)
if [ -n "$O" ]; then
    "$O" insolation utm.tif $NOON -o old_gles.tif --quiet
    "$O" insolation utm.tif $NOON -o old_truth.tif --backend truth --quiet
    rows+=(old_gles.tif old_truth.tif)
fi
$PY - truth128.tif "${rows[@]}" <<'PY'
import sys
from osgeo import gdal
import numpy as np
def share(f):
    d = gdal.Open(f)
    wh = float(d.GetMetadataItem("HFS_DIFFUSE_HORIZONTAL_WH"))
    return d.GetRasterBand(2).ReadAsArray().astype(np.float64)[2:-2, 2:-2] / wh
t = share(sys.argv[1])
print("| run | mean S | mean err | p99 | max |\n|---|---|---|---|---|")
for f in sys.argv[2:]:
    s = share(f); e = np.abs(s - t)
    print("| %s | %.4f | %.5f | %.4f | %.4f |" % (f[:-4], s.mean(), e.mean(),
                                                 np.percentile(e, 99), e.max()))
PY
tm() { /usr/bin/time -f "%e" "$@" 2>&1 >/dev/null | tail -1; }
new=() old=()
for r in $(seq "$ROUNDS"); do
    new+=("$(tm "$H" insolation utm.tif $DAY -o day.tif --quiet)")
    [ -n "$O" ] && old+=("$(tm "$O" insolation utm.tif $DAY -o day_old.tif --quiet)")
done
med() { printf '%s\n' "$@" | sort -g | awk '{a[NR] = $1} END {print a[int((NR + 1) / 2)]}'; }
echo "a June day, 30-minute steps, GLES: $(med "${new[@]}") s (median of $ROUNDS)"
[ -n "$O" ] && echo "the same with $OLD: $(med "${old[@]}") s"
exit 0
