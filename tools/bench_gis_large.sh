#!/usr/bin/env bash
# A large DEM's GIS products beside the tools terrain analysts use (issue 39
# item 3: "an hfgen fractal at 1024² and 4096²").  tools/bench_gis.sh runs
# every product at full settings; at 4096² that would take hours (the
# peers' searches grow with the texels times the rays' length: r.horizon's
# 16 azimuths about 40 minutes, r.sun's day of 30-minute steps about half
# an hour).  This runs each product at lighter settings, the same for both
# tools, on one machine in one run, hfshade's `--method sweep` (ROUNDS
# runs, the median) against the peer (one run; GRASS's start included, as
# in bench_gis.sh), each against the truth where one is affordable:
#   horizon     `hfshade horizon` and GRASS `r.horizon -d` at the azimuths
#               START + k STEP below 360 (r.horizon's start= and step=: it
#               makes floor((360 - START) / STEP) of them; given to hfshade
#               as a list); the default's are off the grid's axes and
#               diagonals, along which the sweep's lines are the texels'
#               own rays (exact there).  Against the truth backend's exact
#               horizons, degrees, r.horizon's clamped at 0 as SPEC does.
#   svf         `hfshade svf --directions D` and SAGA's sky-view factor
#               (ta_lighting 3, NDIRS D, the whole DEM), each against the
#               truth of its own quantity as bench_gis.sh measures it (the
#               Zaksek SVF; SAGA's "visible sky" on the truth's horizons at
#               its compass directions).  LARGE_SVF_DIRS (default 5: SAGA's
#               and hfshade's directions then share one axis only).
#   insolation  `hfshade insolation --beam-only` and GRASS `r.sun` mode 2
#               (beam_rad alone) over 2026-06-21 in steps of
#               LARGE_SUN_STEP_H hours (default 2); no truth (a truth
#               render a step is hours at 4096²): the time, and both days'
#               mean beam.
# The products: LARGE_PRODUCTS (default "horizon"; e.g. "horizon svf
# insolation").  Errors over the DEM less a 2-texel border.  The DEM: an
# `hfgen fractal` field of N x N as a UTM 16N GeoTIFF with 30 m cells
# (SRTM's), as bench_gis.sh's fractal:N.  Installs its peers (grass-core,
# saga, gdal-bin, python3-gdal, python3-numpy) with apt when they are
# missing: they are not the product's dependencies.
# usage: tools/bench_gis_large.sh [BUILD] [N] [STEP] [START] [ROUNDS]
#   (default build 4096 90 22.5 3: azimuths 22.5, 112.5, 202.5)
set -euo pipefail
cd "$(dirname "$0")/.."
B=${1:-build}
N=${2:-4096}
STEP=${3:-90}
START=${4:-22.5}
ROUNDS=${5:-3}
PRODUCTS=${LARGE_PRODUCTS:-horizon}
SVF_DIRS=${LARGE_SVF_DIRS:-5}
SUN_STEP_H=${LARGE_SUN_STEP_H:-2}
H="$(pwd)/$B/tools/hfshade"
PY=/usr/bin/python3
. tools/bench_gdal.sh
bench_gdal_need grass-core saga # the peers (with gdal-bin, python3-gdal, numpy)
R=$(pwd)
C=$(mktemp -d)
trap 'rm -rf "$C"' EXIT
cd "$C"
bench_fractal_utm "$R" "$B" "$N" utm.tif
echo "## fractal:$N: ${N}x$N, 30 m cells, whole DEM, products: $PRODUCTS"
now() { date +%s.%N; }
secs() { awk -v a="$1" -v b="$(now)" 'BEGIN {printf "%.3f\n", b - a}'; }
median() { sort -n "$1" | awk '{v[NR] = $1} END {print v[int((NR + 1) / 2)]}'; }
# ours NAME ARGS...: ROUNDS timed runs of hfshade ARGS into NAME.t
ours() {
    local name=$1 t0
    shift
    for _ in $(seq "$ROUNDS"); do
        t0=$(now)
        "$H" "$@" --quiet
        secs "$t0" >>"$name.t"
    done
}
# grass_run SCRIPT [TIMES]: runs SCRIPT in the DEM's GRASS location, its
# wall seconds into TIMES when given
grass_run() {
    local t0
    t0=$(now)
    grass gdb/l/PERMANENT --exec bash "$1" >/dev/null 2>&1
    if [ -n "${2:-}" ]; then secs "$t0" >"$2"; fi
}
grass -c utm.tif -e gdb/l >/dev/null 2>&1
printf 'r.in.gdal -o input=utm.tif output=dem --overwrite --quiet\ng.region raster=dem\n' >import.sh
grass_run import.sh
echo "| tool | quantity | time (s) | mean error | p99 | max |"
echo "|---|---|---|---|---|---|"
stats() { # TIME NAME QUANTITY OURS_TIF TRUTH_TIF [CLAMP]: one table row
    $PY - "$@" <<'EOF'
import sys
import numpy as np
from osgeo import gdal
gdal.UseExceptions()
t, name, what, a, b = sys.argv[1:6]
clamp = len(sys.argv) > 6
def rd(p):  # the dataset kept open while its band is read (GDAL's Python)
    ds = gdal.Open(p)
    a = ds.GetRasterBand(1).ReadAsArray().astype(np.float64)
    ds = None
    return a[2:-2, 2:-2]
x = rd(a)
d = np.abs((np.maximum(x, 0.0) if clamp else x) - rd(b)).ravel()
print("| %s | %s | %.2f | %.3g | %.3g | %.3g |" % (name, what, float(t), d.mean(),
                                                  np.percentile(d, 99), d.max()))
EOF
}

for product in $PRODUCTS; do
case $product in
horizon)
    mkdir -p tru sweep rh
    AZ=$(awk -v s="$START" -v d="$STEP" 'BEGIN {n = int((360 - s) / d + 1e-9);
        for (k = 0; k < n; ++k) printf "%s%.6g", k ? "," : "", s + k * d}')
    RSTEP=$(awk -v d="$STEP" 'BEGIN {printf (d == int(d) ? "%.1f" : "%.6g"), d}') # names
    "$H" horizon utm.tif --azimuths "$AZ" --backend truth --quiet -o tru/hor
    ours hor horizon utm.tif --azimuths "$AZ" --method sweep -o sweep/hor
    echo "r.horizon elevation=dem start=$START step=$RSTEP output=hor -d --overwrite --quiet" \
        >rhor.sh
    grass_run rhor.sh rh.t
    cat >rout.sh <<'EOF'
for m in $(g.list raster pattern='hor_*'); do
    r.out.gdal -c input=$m output=rh/$m.tif format=GTiff type=Float32 --quiet --overwrite
done
EOF
    grass_run rout.sh
    $PY - "$(median hor.t)" "$(cat rh.t)" <<'EOF'
import glob, os, sys
import numpy as np
from osgeo import gdal
gdal.UseExceptions()
t_sw, t_rh = (float(v) for v in sys.argv[1:3])
def rd(p):  # the dataset kept open while its band is read (GDAL's Python)
    ds = gdal.Open(p)
    a = ds.GetRasterBand(1).ReadAsArray().astype(np.float64)
    ds = None
    return a[2:-2, 2:-2]
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
EOF
    ;;
svf)
    "$H" svf utm.tif --directions "$SVF_DIRS" --backend truth --quiet -o tru_svf.tif
    ours svf svf utm.tif --directions "$SVF_DIRS" --method sweep -o sweep_svf.tif
    t0=$(now)
    saga_cmd -f=s ta_lighting 3 -DEM utm.tif -VISIBLE saga_vis.sdat -SVF saga_svf.sdat \
        -RADIUS 100000000 -NDIRS "$SVF_DIRS" -METHOD 0 >/dev/null 2>&1
    secs "$t0" >saga.t
    # SAGA's visible sky on the truth's horizons at its compass directions
    CAZ=$(awk -v n="$SVF_DIRS" 'BEGIN {for (k = 0; k < n; ++k)
        printf "%s%.6g", k ? "," : "", 360 * k / n}')
    mkdir -p cmp
    "$H" horizon utm.tif --convention compass --azimuths "$CAZ" --backend truth --quiet \
        -o cmp/c
    $PY -c "
import glob
import numpy as np
from osgeo import gdal
gdal.UseExceptions()
def rd(p):
    ds = gdal.Open(p)
    a = ds.GetRasterBand(1).ReadAsArray().astype(np.float64)
    ds = None
    return a
g = [np.radians(rd(f)) for f in sorted(glob.glob('cmp/c_*.tif'))]
v = np.mean([(np.pi / 2 - x) / (np.pi / 2) for x in g], axis=0)
s = rd('saga_vis.sdat') / 100.0
for name, a in (('tru_vis.tif', v), ('saga_vis.tif', s)):
    d = gdal.GetDriverByName('GTiff').Create(name, a.shape[1], a.shape[0], 1, gdal.GDT_Float32)
    d.GetRasterBand(1).WriteArray(a.astype(np.float32))
    d = None"
    stats "$(median svf.t)" "hfshade svf --method sweep (median)" \
        "sky-view factor (Zaksek), $SVF_DIRS directions" sweep_svf.tif tru_svf.tif
    stats "$(cat saga.t)" "SAGA sky view factor (one run)" \
        "visible sky (SAGA's), fraction, $SVF_DIRS directions" saga_vis.tif tru_vis.tif
    ;;
insolation)
    ours ins insolation utm.tif --from 2026-06-21T00:00 --to 2026-06-22T00:00 \
        --timezone -05:00 --step "$((SUN_STEP_H * 60))" --linke 3 --method sweep --beam-only \
        -o beam.tif
    printf 'r.slope.aspect elevation=dem slope=slope aspect=aspect --overwrite --quiet\n' \
        >rslope.sh
    grass_run rslope.sh
    printf 'r.sun elevation=dem slope=slope aspect=aspect day=172 step=%s linke_value=3 beam_rad=beam --overwrite --quiet\n' \
        "$SUN_STEP_H" >rsun.sh
    grass_run rsun.sh rsun.t
    printf 'r.out.gdal -c input=beam output=rsun_beam.tif format=GTiff type=Float32 --quiet --overwrite\n' \
        >rout.sh
    grass_run rout.sh
    $PY - "$(median ins.t)" "$(cat rsun.t)" "$SUN_STEP_H" <<'EOF'
import sys
import numpy as np
from osgeo import gdal
gdal.UseExceptions()
t_o, t_r, step = float(sys.argv[1]), float(sys.argv[2]), sys.argv[3]
def mean(p):
    ds = gdal.Open(p)
    b = ds.GetRasterBand(1)
    a = b.ReadAsArray().astype(np.float64)
    nd = b.GetNoDataValue()
    ds = None
    return float(np.nanmean(np.where(a == nd, np.nan, a) if nd is not None else a))
m = [mean(p) for p in ("beam.tif", "rsun_beam.tif")]
print("| hfshade insolation --method sweep --beam-only (median) | beam of 2026-06-21, "
      "%s-hour steps, Wh/m² (mean %.0f) | %.2f | n/a | | |" % (step, m[0], t_o))
print("| GRASS r.sun mode 2, beam_rad alone (one run) | the same (mean %.0f) | %.2f | n/a | | |"
      % (m[1], t_r))
EOF
    ;;
*)
    echo "bench_gis_large.sh: '$product' is not horizon, svf or insolation" >&2
    exit 2
    ;;
esac
done
