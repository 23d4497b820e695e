#!/usr/bin/env bash
# The horizons of a large DEM beside GRASS r.horizon (issue 39 item 3: "an
# hfgen fractal at 1024² and 4096²").  tools/bench_gis.sh runs every
# product and every peer; at 4096² that would take hours (r.horizon's work
# grows with the texels times the rays' length: about 90 minutes for its 16
# azimuths).  This runs the horizons alone, at the same few azimuths for
# both tools, on one machine in one run:
#   - `hfshade horizon --method sweep` (ROUNDS runs, the median) and GRASS
#     `r.horizon -d` (one run; it starts a GRASS session, as in
#     bench_gis.sh), the whole DEM searched by both;
#   - each against the truth backend's exact horizons (`hfshade horizon
#     --backend truth`, not timed), degrees, r.horizon's clamped at 0 as
#     SPEC does, over the DEM less a 2-texel border.
# The DEM: an `hfgen fractal` field of N x N as a UTM 16N GeoTIFF with 30 m
# cells (SRTM's), as bench_gis.sh's fractal:N.  Installs its peers
# (grass-core, gdal-bin, python3-gdal, python3-numpy) with apt when they
# are missing: they are not the product's dependencies.
# The azimuths: START + k STEP below 360 (r.horizon's start= and step=:
# it makes floor((360 - START) / STEP) of them), given to hfshade as a
# list; the default's are off the grid's axes and diagonals, along which
# the sweep's lines are the texels' own rays (exact there).
# usage: tools/bench_gis_large.sh [BUILD] [N] [STEP] [START] [ROUNDS]
#   (default build 4096 90 22.5 3: azimuths 22.5, 112.5, 202.5)
set -euo pipefail
cd "$(dirname "$0")/.."
B=${1:-build}
N=${2:-4096}
STEP=${3:-90}
START=${4:-22.5}
ROUNDS=${5:-3}
H="$(pwd)/$B/tools/hfshade"
PY=/usr/bin/python3
need=()
command -v gdalinfo >/dev/null || need+=(gdal-bin)
command -v grass >/dev/null || need+=(grass-core)
$PY -c "from osgeo import gdal; import numpy" 2>/dev/null || need+=(python3-gdal python3-numpy)
if [ ${#need[@]} -gt 0 ]; then
    echo "installing the peers: ${need[*]}" >&2
    DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends "${need[@]}" >&2
fi
R=$(pwd)
C=$(mktemp -d)
trap 'rm -rf "$C"' EXIT
cd "$C"
"$R/$B/tools/hfgen" fractal --size "${N}x$N" -o f.pfm
$PY "$R/tools/bench_dem.py" f.pfm utm.tif 30
rm f.pfm
echo "## fractal:$N: ${N}x$N, 30 m cells, azimuths every $STEP degrees from $START, whole DEM"
now() { date +%s.%N; }
mkdir -p tru sweep rh
AZ=$(awk -v s="$START" -v d="$STEP" 'BEGIN {n = int((360 - s) / d + 1e-9);
    for (k = 0; k < n; ++k) printf "%s%.6g", k ? "," : "", s + k * d}')
RSTEP=$(awk -v d="$STEP" 'BEGIN {printf (d == int(d) ? "%.1f" : "%.6g"), d}') # r.horizon names
echo "## azimuths (ccw from east): $AZ"
t0=$(now)
"$H" horizon utm.tif --azimuths "$AZ" --backend truth --quiet -o tru/hor
echo "(the truth: $(awk -v a="$t0" -v b="$(now)" 'BEGIN {printf "%.0f", b - a}') s)"
for _ in $(seq "$ROUNDS"); do
    t0=$(now)
    "$H" horizon utm.tif --azimuths "$AZ" --method sweep --quiet -o sweep/hor
    awk -v a="$t0" -v b="$(now)" 'BEGIN {printf "%.3f\n", b - a}' >>sweep.t
done
grass -c utm.tif -e gdb/l >/dev/null 2>&1
cat >run.sh <<EOF
r.in.gdal -o input=utm.tif output=dem --overwrite --quiet
g.region raster=dem
EOF
grass gdb/l/PERMANENT --exec bash run.sh >/dev/null 2>&1
echo "r.horizon elevation=dem start=$START step=$RSTEP output=hor -d --overwrite --quiet" >rhor.sh
t0=$(now)
grass gdb/l/PERMANENT --exec bash rhor.sh >/dev/null 2>&1
awk -v a="$t0" -v b="$(now)" 'BEGIN {printf "%.3f\n", b - a}' >rh.t
cat >rout.sh <<'EOF'
for m in $(g.list raster pattern='hor_*'); do
    r.out.gdal -c input=$m output=rh/$m.tif format=GTiff type=Float32 --quiet --overwrite
done
EOF
grass gdb/l/PERMANENT --exec bash rout.sh >/dev/null 2>&1
median() { sort -n "$1" | awk '{v[NR] = $1} END {print v[int((NR + 1) / 2)]}'; }
$PY - "$(median sweep.t)" "$(cat rh.t)" <<'EOF'
import glob, os, sys
import numpy as np
from osgeo import gdal
gdal.UseExceptions()
t_sw, t_rh = (float(v) for v in sys.argv[1:3])
def rd(p):
    ds = gdal.Open(p)
    a = ds.GetRasterBand(1).ReadAsArray().astype(np.float64)
    ds = None
    return a[2:-2, 2:-2]
print("| tool | quantity | time (s) | mean error | p99 | max |")
print("|---|---|---|---|---|---|")
files = sorted(glob.glob("tru/hor_*.tif"))
for name, sub, t, clamp in (("hfshade horizon --method sweep (median)", "sweep", t_sw, False),
                            ("GRASS r.horizon (one run)", "rh", t_rh, True)):
    e = []
    for f in files:
        a = rd(os.path.join(sub, os.path.basename(f)))
        e.append(np.abs((np.maximum(a, 0.0) if clamp else a) - rd(f)).ravel())
    d = np.concatenate(e)
    print("| %s | horizon angle, %d azimuths, deg | %.2f | %.3g | %.3g | %.3g |"
          % (name, len(files), t, d.mean(), np.percentile(d, 99), d.max()))
print("\nspeed: r.horizon / hfshade horizon --method sweep %.1fx" % (t_rh / t_sw))
EOF
