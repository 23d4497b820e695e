#!/usr/bin/env bash
# A DEM's windows as jobs for GNU parallel (issue 40 item 1; docs/GIS.md
# "Many machines"): an `hfgen fractal` field of N x N (default 4096) as a
# UTM GeoTIFF with 30 m cells (tools/bench_dem.py), a PRODUCT of it (GLES)
# cut into tiles of TILE texels (default 1024: 16 jobs), four ways, wall
# time of each.  PRODUCT: svf (default; 8 directions within RADIUS
# metres), sun (2026-06-21 06:30 local; RADIUS 0: the halo is the reach of
# its shadows), insolation (that day 05:00-21:00 in hourly steps, the
# sky's 16 azimuths and the shadows within RADIUS) or render (the lit
# render of a uniform sky and a 20-degree sun at --zscale 0.1; RADIUS
# unused: the halo is the render's own, from the relief and the lights; at
# zscale 1 the fractal's relief of about 1 km makes it some 1550 texels,
# and every job renders most of the DEM):
#   single     one process streams it: `hfshade svf --tile TILE` (render:
#              one process renders it whole, `hfshade render --geotiff`);
#   sequential the plan's jobs one after the other (`parallel -j1`), merged;
#   parallel   the same plan on the cores (`parallel -j JOBS`), merged;
#   resumed    the same plan killed (SIGKILL to parallel and its jobs) once
#              half the tiles are written, then `parallel --resume-failed`
#              with the same joblog, merged.
# Checks: each mosaic byte for byte the sequential one's (cmp), and its
# values (every band) bit for bit the single run's (render: the largest
# difference, relative to the largest value).  Installs GNU parallel, python3-gdal
# and python3-numpy when missing (tools/install-deps.sh has parallel).
# usage: tools/bench_tiles.sh [BUILD] [N] [TILE] [RADIUS] [JOBS] [PRODUCT]
#   e.g. tools/bench_tiles.sh build 4096 1024 600 2
#        tools/bench_tiles.sh build 4096 1024 0 2 sun
set -euo pipefail
cd "$(dirname "$0")/.."
B=${1:-build}
N=${2:-4096}
TILE=${3:-1024}
RADIUS=${4:-600}
JOBS=${5:-2}
PRODUCT=${6:-svf}
H="$(pwd)/$B/tools/hfshade"
PY=/usr/bin/python3
need=()
command -v parallel >/dev/null || need+=(parallel)
$PY -c "from osgeo import gdal; import numpy" 2>/dev/null || need+=(python3-gdal python3-numpy)
if [ ${#need[@]} -gt 0 ]; then
    DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends "${need[@]}" >&2
fi
C=$(mktemp -d)
trap 'rm -rf "$C"' EXIT
"$B/tools/hfgen" fractal --size "${N}x$N" -o "$C/f.pfm"
$PY tools/bench_dem.py "$C/f.pfm" "$C/dem.tif" 30
case "$PRODUCT" in
svf) OPTS=(--radius "$RADIUS" --directions 8) ;;
sun) OPTS=(--datetime 2026-06-21T06:30-05:00 --radius "$RADIUS") ;;
insolation) OPTS=(--from 2026-06-21T05:00-05:00 --to 2026-06-21T21:00-05:00 --step 60
                  --radius "$RADIUS") ;;
render) OPTS=(--dx 30 --zscale 0.1 --env-sh 3.5449,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0
               --key 135,20,0.5,10000) ;;
*) echo "bench_tiles.sh: PRODUCT '$PRODUCT' is not svf, sun, insolation or render" >&2; exit 2 ;;
esac
now() { date +%s.%N; }
since() { awk -v a="$1" -v b="$(now)" 'BEGIN {printf "%.1f", b - a}'; }
cd "$C"

t=$(now)
if [ "$PRODUCT" = render ]; then
    "$H" render --height dem.tif "${OPTS[@]}" --geotiff single.tif 2>&1 | sed 's/^/  /'
else
    "$H" "$PRODUCT" dem.tif "${OPTS[@]}" --tile "$TILE" -o single.tif 2>&1 | sed 's/^/  /'
fi
echo "single process ($([ "$PRODUCT" = render ] && echo whole || echo "streamed, --tile $TILE")): $(since "$t") s"

plan_run() { # DIR PARALLEL-OPTIONS...: plan, run, merge; prints the wall time
    local dir=$1 t
    shift
    t=$(now)
    "$H" tiles plan dem.tif --product "$PRODUCT" --tile "$TILE" -o "$dir" "${OPTS[@]}"
    parallel "$@" --joblog "$dir/log" "$H" tiles run "$dir/manifest" {} :::: "$dir/jobs" 2>/dev/null
    "$H" tiles merge "$dir" -o "$dir.tif" 2>/dev/null
    echo "$(since "$t")"
}
echo "sequential jobs (parallel -j1), plan + run + merge: $(plan_run seq -j1) s"
echo "  $(wc -l <seq/jobs) jobs, the first: $(head -1 seq/jobs) (K IX IY IW IH HALO FILES)"
echo "parallel -j$JOBS, plan + run + merge: $(plan_run par "-j$JOBS") s"

# killed half-way, then resumed
t=$(now)
"$H" tiles plan dem.tif --product "$PRODUCT" --tile "$TILE" -o res "${OPTS[@]}"
total=$(wc -l <res/jobs)
setsid parallel "-j$JOBS" --joblog res/log "$H" tiles run res/manifest {} :::: res/jobs \
    >/dev/null 2>&1 &
pid=$!
while [ "$(find res/tiles -name '*.tif' | wc -l)" -lt $((total / 2)) ]; do sleep 0.2; done
kill -KILL -- -"$pid" 2>/dev/null || true
wait "$pid" 2>/dev/null || true
done_then=$(find res/tiles -name '*.tif' | wc -l)
left=$(find res/tiles -name '*.tmp-*' | wc -l)
parallel "-j$JOBS" --resume-failed --joblog res/log "$H" tiles run res/manifest {} \
    :::: res/jobs 2>/dev/null
"$H" tiles merge res -o res.tif 2>/dev/null
echo "killed with $done_then of $total tiles written ($left temporaries left), resumed and" \
     "merged: $(since "$t") s in all"

for m in par res; do
    if cmp -s seq.tif "$m.tif"; then echo "$m.tif: byte for byte seq.tif"; else echo "$m.tif: DIFFERS"; fi
done
$PY - <<'EOF'
import numpy as np
from osgeo import gdal
gdal.UseExceptions()
def rd(p):
    ds = gdal.Open(p)
    a = np.stack([ds.GetRasterBand(k + 1).ReadAsArray() for k in range(ds.RasterCount)])
    ds = None
    return a
a, b = rd("single.tif"), rd("seq.tif")
print("mosaic against the single process: %s (%d values differ; largest difference %.3g of "
      "the largest value)"
      % ("bit for bit" if np.array_equal(a.view(np.uint32), b.view(np.uint32)) else "not bit for bit",
         int((a.view(np.uint32) != b.view(np.uint32)).sum()),
         float(np.abs(a.astype(np.float64) - b).max() / max(np.abs(a).max(), 1e-30))))
EOF
