#!/usr/bin/env bash
# insolation with a sky map and the ground's reflection (docs/GIS.md "The
# sun": --sky-map, --albedo) on the Jacksboro DEM in UTM 16N with 83 m
# cells (as tools/bench_sky_share.sh), a sky ten times brighter within 45
# degrees of north than elsewhere (a 64 x 32 PFM made here):
#   - the map's share S (band 2 over the clear sky's diffuse horizontal
#     irradiation), one 30-minute step at noon, GLES at the default 16
#     azimuths and the isotropic sky's for reference, each against the
#     truth's exact horizons in 128 azimuths with the same sky, over the DEM
#     less a 2-texel border: mean, p99 and max of |S - S_truth|;
#   - a June day in 30-minute steps on GLES, timed (median of ROUNDS, the
#     three runs alternating): isotropic, --sky-map, --sky-map --albedo 0.2.
# Installs gdal-bin, python3-gdal and python3-numpy when missing.
# usage: tools/bench_sky_map.sh [BUILD] [ROUNDS]
set -euo pipefail
cd "$(dirname "$0")/.."
B=${1:-build}
ROUNDS=${2:-3}
H="$(pwd)/$B/tools/hfshade"
PY=/usr/bin/python3
. tools/bench_gdal.sh
bench_gdal_need
bench_jacksboro_workdir "$(pwd)"
$PY - <<'PY'
import numpy as np
h, w = 32, 64
compass = 360.0 * (np.arange(w) + 0.5) / w
row = np.where((compass < 45.0) | (compass > 315.0), 10.0, 1.0)
sky = np.repeat(np.tile(row, (h, 1))[:, :, None], 3, axis=2).astype("<f4")
with open("north.pfm", "wb") as f:
    f.write(b"PF\n%d %d\n-1.0\n" % (w, h))
    f.write(sky.tobytes())
PY
NOON="--from 2026-06-21T12:00-05:00 --to 2026-06-21T12:30-05:00 --step 30"
DAY="--from 2026-06-21T05:00-05:00 --to 2026-06-21T21:00-05:00 --step 30"
MAP="--sky-map north.pfm"
"$H" insolation utm.tif $NOON -o truth_map.tif --backend truth --directions 128 $MAP --quiet
"$H" insolation utm.tif $NOON -o truth_iso.tif --backend truth --directions 128 --quiet
"$H" insolation utm.tif $NOON -o gles_map.tif $MAP --quiet
"$H" insolation utm.tif $NOON -o gles_iso.tif --quiet
$PY - <<'PY'
from osgeo import gdal
import numpy as np
def share(f):
    d = gdal.Open(f)
    wh = float(d.GetMetadataItem("HFS_DIFFUSE_HORIZONTAL_WH"))
    return d.GetRasterBand(2).ReadAsArray().astype(np.float64)[2:-2, 2:-2] / wh
print("| sky | mean S | mean err | p99 | max |\n|---|---|---|---|---|")
for sky in ("map", "iso"):
    s, t = share("gles_%s.tif" % sky), share("truth_%s.tif" % sky)
    e = np.abs(s - t)
    print("| %s | %.4f | %.5f | %.4f | %.4f |" % (sky, s.mean(), e.mean(),
                                                 np.percentile(e, 99), e.max()))
PY
for k in $(seq "$ROUNDS"); do
    for v in iso map albedo; do
        case $v in
            iso) extra="" ;;
            map) extra="$MAP" ;;
            albedo) extra="$MAP --albedo 0.2" ;;
        esac
        s=$(date +%s.%N)
        "$H" insolation utm.tif $DAY -o day_$v.tif $extra --quiet
        echo "$v $(echo "$(date +%s.%N) - $s" | bc)" >> times.txt
    done
done
for v in iso map albedo; do
    printf "day, %s: median %.2f s of %s\n" "$v" \
        "$(grep "^$v " times.txt | awk '{print $2}' | sort -g | awk '{a[NR]=$1} END{print a[int((NR+1)/2)]}')" \
        "$ROUNDS"
done
