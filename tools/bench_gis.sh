#!/usr/bin/env bash
# The GIS rasters side by side with the tools terrain analysts use (issue
# 39): GRASS r.horizon and SAGA's sky-view factor against hfshade's
# `horizon` and `svf` (GLES, the default; the CPU reference too), each
# against the truth of ITS OWN quantity from hfshade's truth backend (exact
# horizons of the bilinear surface), on one DEM, on this machine, in one
# run.  Wall-clock medians of ROUNDS runs, rounds alternating between the
# tools.  Installs its peers (grass-core, saga, gdal-bin, python3-gdal,
# python3-numpy) with apt when they are missing: they are not the
# product's dependencies.
#   - DEM: data/jacksboro.png placed in UTM 16N (EPSG:32616) with square
#     83 m cells (the demo's dx) as a Float32 GeoTIFF, so every tool reads
#     the same metres; the geographic 3 arc-second GeoTIFF of the same DEM
#     shows the outputs on the input's own grid (gdalinfo).
#   - horizons: 16 azimuths every 22.5 deg counter-clockwise from east
#     (r.horizon's convention and file names), the whole DEM searched
#     (r.horizon's and hfshade's defaults), degrees, clamped at 0 as SPEC
#     does (r.horizon also gives negative angles); errors over the DEM less
#     a 2-texel border.
#   - sky-view factor: SAGA ta_lighting 3 with 16 sectors, radius 100 km
#     (the whole DEM), its "Visible Sky" (the mean of (90 - gamma) / 90,
#     gamma clamped at 0: SAGA's view_shed.cpp) against that formula on the
#     truth's horizons at SAGA's directions (compass 0, 22.5, ...);
#     hfshade's Zaksek sky-view factor against the truth's.
#   - insolation: the day of 2026-06-21 (r.sun day=172), 30-minute steps,
#     Linke turbidity 3, terrain shadowing on: r.sun's beam irradiation
#     (mode 2, Wh/m^2; slope and aspect from r.slope.aspect, not timed)
#     and `hfshade insolation`'s band 1, each against `hfshade insolation
#     --backend truth`'s (the same ESRA beam, exact shadows).  Only the
#     beam: r.sun's diffuse is Muneer's anisotropic model, hfshade's an
#     isotropic sky over exact horizons (docs/GIS.md), not one quantity.
#     r.sun computes the beam alone here (beam_rad only); so does
#     `hfshade insolation --beam-only` (its time is the like-for-like one;
#     the plain command also searches the sky's 16 azimuths).
#     hfshade's day runs in local time (-05:00, about the DEM's solar time)
#     so that the daylight falls in one period as r.sun's does.
#   - DEM fractal:N instead: an `hfgen fractal` field of N x N as a UTM 16N
#     GeoTIFF with 30 m cells (SRTM's), the same commands; RADIUS (metres,
#     0: the whole DEM) bounds every search (r.horizon maxdistance, SAGA
#     RADIUS, hfshade --radius; r.sun has none).  The truth of a day's
#     insolation (a truth render of the sun a step) is measured on the
#     Jacksboro DEM only: on 1024^2 it would take about 20 minutes.
# usage: tools/bench_gis.sh [BUILD] [ROUNDS] [DEM] [RADIUS]
#   (default build 3 jacksboro 0; e.g. tools/bench_gis.sh build 1 fractal:1024)
set -euo pipefail
cd "$(dirname "$0")/.."
B=${1:-build}
ROUNDS=${2:-3}
DEM=${3:-jacksboro}
RADIUS=${4:-0}
H="$(pwd)/$B/tools/hfshade"
PY=/usr/bin/python3
. tools/bench_gdal.sh
bench_gdal_need grass-core saga # the peers (with gdal-bin, python3-gdal, numpy)
C=$(mktemp -d)
trap 'rm -rf "$C"' EXIT
cd "$C"
if [ "$DEM" = jacksboro ]; then
    D3=$(awk 'BEGIN {printf "%.12f", 3 / 3600}')
    read -r ULX ULY LRX LRY < <(awk -v d="$D3" 'BEGIN {w = 403; h = 344;
        x = -84.25 - 0.5 * w * d; y = 36.25 + 0.5 * h * d; printf "%.10f %.10f %.10f %.10f\n", x, y, x + w * d, y - h * d}')
    gdal_translate -q -ot Int16 -a_srs EPSG:4326 -a_ullr "$ULX" "$ULY" "$LRX" "$LRY" -a_nodata -32768 \
        "$OLDPWD/data/jacksboro.png" geo.tif
    bench_jacksboro_utm "$OLDPWD" utm.tif
    echo "## Outputs on the input's grid (the geographic 3 arc-second DEM)"
    "$H" svf geo.tif --quiet -o geo_svf.tif
    for f in geo.tif geo_svf.tif; do
        echo "$f: $(gdalinfo "$f" | grep -E '^Size is|^Origin|^Pixel Size|NoData' | tr '\n' ';')"
    done
elif [[ "$DEM" =~ ^fractal:([0-9]+)$ ]]; then
    N=${BASH_REMATCH[1]}
    bench_fractal_utm "$OLDPWD" "$B" "$N" utm.tif
    echo "## $DEM: ${N}x$N, 30 m cells, $(gdalinfo -stats utm.tif | grep -oE 'Minimum=[^,]*, Maximum=[^,]*' | head -1) m"
else
    echo "bench_gis.sh: DEM '$DEM' is not jacksboro or fractal:N" >&2
    exit 2
fi
# the searches' reach: hfshade's --radius, r.horizon's maxdistance, SAGA's RADIUS
HR=() RH="" SR=100000000
if [ "$RADIUS" != 0 ]; then
    HR=(--radius "$RADIUS") RH="maxdistance=$RADIUS" SR=$RADIUS
fi
echo "## search radius: ${RADIUS} m (0: the whole DEM)"
# --method sweep searches the whole DEM only: with a radius its rows are n/a
SW=(--method sweep)
[ "$RADIUS" = 0 ] || SW=(--method sweep --radius "$RADIUS")

mkdir -p tru gles cpu sweep rh
"$H" horizon utm.tif --step 22.5 "${HR[@]}" --backend truth --quiet -o tru/hor
"$H" horizon utm.tif --convention compass --step 22.5 "${HR[@]}" --backend truth --quiet -o tru/cmp
"$H" svf utm.tif "${HR[@]}" --backend truth --quiet -o tru_svf.tif
grass -c utm.tif -e gdb/jb >/dev/null 2>&1
cat >import.sh <<'EOF'
r.in.gdal -o input=utm.tif output=dem --overwrite --quiet
g.region raster=dem
EOF
grass gdb/jb/PERMANENT --exec bash import.sh >/dev/null 2>&1

now() { date +%s.%N; }
# time_of NAME CMD...: appends the wall seconds of one run to NAME.t
time_of() {
    local name=$1 t0
    shift
    t0=$(now)
    "$@" >/dev/null 2>&1
    awk -v a="$t0" -v b="$(now)" 'BEGIN {printf "%.3f\n", b - a}' >>"$name.t"
}
cat >rhor.sh <<EOF
r.horizon elevation=dem step=22.5 $RH output=hor -d --overwrite --quiet
EOF
cat >rslope.sh <<'EOF'
r.slope.aspect elevation=dem slope=slope aspect=aspect --overwrite --quiet
EOF
grass gdb/jb/PERMANENT --exec bash rslope.sh >/dev/null 2>&1
cat >rsun.sh <<'EOF'
r.sun elevation=dem slope=slope aspect=aspect day=172 step=0.5 linke_value=3 \
    beam_rad=beam --overwrite --quiet
EOF
DAY="--from 2026-06-21T00:00 --to 2026-06-22T00:00 --timezone -05:00 --step 30 --linke 3"
if [ "$DEM" = jacksboro ]; then
    # shellcheck disable=SC2086 # DAY's flags are words
    "$H" insolation utm.tif $DAY --backend truth --quiet -o tru_ins.tif
fi
for _ in $(seq "$ROUNDS"); do
    time_of hf_horizon_gles "$H" horizon utm.tif --step 22.5 "${HR[@]}" --quiet -o gles/hor
    time_of hf_horizon_cpu "$H" horizon utm.tif --step 22.5 "${HR[@]}" --backend cpu --quiet \
        -o cpu/hor
    time_of hf_horizon_sweep "$H" horizon utm.tif --step 22.5 "${SW[@]}" --quiet -o sweep/hor
    time_of r_horizon grass gdb/jb/PERMANENT --exec bash rhor.sh
    time_of hf_svf_gles "$H" svf utm.tif "${HR[@]}" --quiet -o gles_svf.tif
    time_of hf_svf_sweep "$H" svf utm.tif "${SW[@]}" --quiet -o sweep_svf.tif
    time_of saga_svf saga_cmd -f=s ta_lighting 3 -DEM utm.tif -VISIBLE saga_vis.sdat \
        -SVF saga_svf.sdat -RADIUS "$SR" -NDIRS 16 -METHOD 0
    # shellcheck disable=SC2086
    time_of hf_ins_gles "$H" insolation utm.tif $DAY --quiet -o gles_ins.tif
    # shellcheck disable=SC2086
    time_of hf_ins_sweep "$H" insolation utm.tif $DAY --method sweep --quiet -o sweep_ins.tif
    # shellcheck disable=SC2086
    time_of hf_ins_beam "$H" insolation utm.tif $DAY --method sweep --beam-only --quiet \
        -o beam_ins.tif
    time_of r_sun grass gdb/jb/PERMANENT --exec bash rsun.sh
done
cat >rout.sh <<'EOF'
for m in $(g.list raster pattern='hor_*'); do
    r.out.gdal -c input=$m output=rh/$m.tif format=GTiff type=Float32 --quiet --overwrite
done
r.out.gdal -c input=beam output=rsun_beam.tif format=GTiff type=Float32 --quiet --overwrite
EOF
grass gdb/jb/PERMANENT --exec bash rout.sh >/dev/null 2>&1
median() { sort -n "$1.t" | awk '{v[NR] = $1} END {print v[int((NR + 1) / 2)]}'; }

$PY - "$(median hf_horizon_gles)" "$(median hf_horizon_cpu)" "$(median hf_horizon_sweep)" \
    "$(median r_horizon)" "$(median hf_svf_gles)" "$(median hf_svf_sweep)" "$(median saga_svf)" \
    "$(median hf_ins_gles)" "$(median hf_ins_sweep)" "$(median r_sun)" "$(median hf_ins_beam)" \
    <<'EOF'
import glob, os, sys
import numpy as np
from osgeo import gdal
gdal.UseExceptions()
t_hg, t_hc, t_hs, t_rh, t_sg, t_ss, t_sa, t_ig, t_is, t_rs, t_ib = (float(v) for v in sys.argv[1:12])
def rd(p):
    if not os.path.exists(p):  # a run that refused (the sweep with a radius): n/a
        return rd(p.replace("sweep", "tru", 1)) * np.nan
    ds = gdal.Open(p)
    a = ds.GetRasterBand(1).ReadAsArray().astype(np.float64)
    ds = None
    return a
def inner(a):
    return a[2:-2, 2:-2]
def stats(d):
    return "%.3g | %.3g | %.3g" % (d.mean(), np.percentile(d, 99), d.max())
rows = []
for name, sub, clamp in (("hfshade horizon (gles)", "gles", False),
                         ("hfshade horizon (cpu)", "cpu", False),
                         ("hfshade horizon --method sweep", "sweep", False),
                         ("GRASS r.horizon", "rh", True)):
    e = []
    for f in sorted(glob.glob("tru/hor_*.tif")):
        t = rd(f)
        a = rd(os.path.join(sub, os.path.basename(f)))
        if clamp:
            a = np.maximum(a, 0.0)
        e.append(inner(np.abs(a - t)).ravel())
    rows.append((name, "horizon angle, deg", np.concatenate(e)))
tz = rd("tru_svf.tif")
rows.append(("hfshade svf (gles)", "sky-view factor (Zaksek)", inner(np.abs(rd("gles_svf.tif") - tz)).ravel()))
rows.append(("hfshade svf --method sweep", "sky-view factor (Zaksek)", inner(np.abs(rd("sweep_svf.tif") - tz)).ravel()))
g = [np.radians(rd(f)) for f in sorted(glob.glob("tru/cmp_*.tif"))]
tv = np.mean([(np.pi / 2 - x) / (np.pi / 2) for x in g], axis=0)
sv = rd("saga_vis.sdat") / 100.0
rows.append(("SAGA sky view factor", "visible sky (SAGA's), fraction", inner(np.abs(sv - tv)).ravel()))
if os.path.exists("tru_ins.tif"):
    tb = rd("tru_ins.tif")
    print("(the truth's day: beam %.0f Wh/m^2 on average)" % tb.mean())
else:  # no truth on this DEM: NaN errors (n/a)
    tb = rd("gles_ins.tif") * np.nan
    print("(no truth of the day's insolation on this DEM: error n/a; hfshade's day %.0f Wh/m^2, "
          "r.sun's %.0f on average)" % (rd("gles_ins.tif").mean(), np.nanmean(rd("rsun_beam.tif"))))
rows.append(("hfshade insolation (gles)", "beam irradiation of a day, Wh/m^2",
             inner(np.abs(rd("gles_ins.tif") - tb)).ravel()))
rows.append(("hfshade insolation --method sweep", "beam irradiation of a day, Wh/m^2",
             inner(np.abs(rd("sweep_ins.tif") - tb)).ravel()))
rows.append(("GRASS r.sun (mode 2)", "beam irradiation of a day, Wh/m^2",
             inner(np.abs(rd("rsun_beam.tif") - tb)).ravel()))
rows.append(("hfshade insolation --method sweep --beam-only", "the same (band 1 alone, as r.sun's "
             "beam_rad)", inner(np.abs(rd("beam_ins.tif") - tb)).ravel()))
times = [t_hg, t_hc, t_hs, t_rh, t_sg, t_ss, t_sa, t_ig, t_is, t_rs, t_ib]
print("| tool | quantity | time (s, median) | mean error | p99 | max |")
print("|---|---|---|---|---|---|")
for (name, what, d), t in zip(rows, times):
    print("| %s | %s | %.2f | %s |" % (name, what, t, stats(d)))
print("\nspeed: r.horizon / hfshade horizon (gles) %.2fx; SAGA / hfshade svf (gles) %.2fx; "
      "r.sun / hfshade insolation (gles) %.2fx" % (t_rh / t_hg, t_sa / t_sg, t_rs / t_ig))
print("with --method sweep: r.horizon / horizon %.2fx; SAGA / svf %.2fx; r.sun / insolation "
      "%.2fx; r.sun / insolation --beam-only (the same quantity) %.2fx"
      % (t_rh / t_hs, t_sa / t_ss, t_rs / t_is, t_rs / t_ib))
EOF
