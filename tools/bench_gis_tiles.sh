#!/usr/bin/env bash
# A DEM larger than the ES 3.0 minimum in tiles (issue 39 item 1): an
# `hfgen fractal` field of WxH (default 8192x6144; heights 0..~1500 m) as
# a GeoTIFF in UTM 16N with 10 m cells, its sky-view factor (`hfshade svf`,
# GLES, DIRS directions within RADIUS metres) once under
# HFS_GL_STRICT_LIMITS=1 (textures of at most 2048 texels: tiles with a
# halo of the radius, runtime/gles/horizons.c) and once at the driver's own
# limit in one piece, and the seam measure: the largest difference between
# the two at the texels within 2 of a tile seam against the largest
# anywhere else (seams every 2048 - 2 halo texels, halo = ceil(radius /
# cell) + 2).  Wall time and peak memory (RSS) of each run.  Both runs
# compute the DEM whole (--tile 0).  With TILE, a third run streams it
# (`hfshade svf --tile TILE`: read, computed and written window by window,
# tools/gis/gis_stream.h) and its difference from the one piece is
# printed: its peak RSS against theirs is what streaming buys.  Needs
# python3-gdal and python3-numpy (installed with apt when missing: bench
# tools, not the product's).
# usage: tools/bench_gis_tiles.sh [BUILD] [WxH] [RADIUS_M] [DIRS] [TILE]
#   e.g. tools/bench_gis_tiles.sh build 4096x3072 300 4 1024
set -euo pipefail
cd "$(dirname "$0")/.."
B=${1:-build}
SIZE=${2:-8192x6144}
RADIUS=${3:-500}
DIRS=${4:-8}
TILE=${5:-}
H="$(pwd)/$B/tools/hfshade"
PY=/usr/bin/python3
$PY -c "from osgeo import gdal; import numpy" 2>/dev/null ||
    DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends \
        python3-gdal python3-numpy >&2
C=$(mktemp -d)
trap 'rm -rf "$C"' EXIT
"$B/tools/hfgen" fractal --size "$SIZE" -o "$C/f.pfm"
$PY - "$C/f.pfm" "$C/dem.tif" <<'EOF'
import sys
import numpy as np
from osgeo import gdal, osr
gdal.UseExceptions()
with open(sys.argv[1], "rb") as f:
    assert f.readline().strip() == b"Pf"
    w, h = (int(v) for v in f.readline().split())
    scale = float(f.readline())
    z = np.frombuffer(f.read(), dtype="<f4" if scale < 0 else ">f4").reshape(h, w)
ds = gdal.GetDriverByName("GTiff").Create(sys.argv[2], w, h, 1, gdal.GDT_Float32,
                                          ["TILED=YES", "COMPRESS=DEFLATE"])
ds.SetGeoTransform((700000.0, 10.0, 0.0, 4100000.0, 0.0, -10.0))
srs = osr.SpatialReference()
srs.ImportFromEPSG(32616)
ds.SetProjection(srs.ExportToWkt())
ds.GetRasterBand(1).WriteArray(z)
ds = None
EOF
run() { # NAME TILE ENV...: the svf, its wall time and peak RSS
    local name=$1 tile=$2
    shift 2
    env "$@" /usr/bin/time -f "$name: %e s, peak RSS %M KiB" "$H" svf "$C/dem.tif" \
        --radius "$RADIUS" --directions "$DIRS" --tile "$tile" -o "$C/$name.tif" 2>&1 |
        sed "s|$C/||"
}
run tiled 0 HFS_GL_STRICT_LIMITS=1
run single 0 HFS_GL_STRICT_LIMITS=0
# seams A B SPACING WHAT: the largest difference of A from B at the texels
# within 2 of a seam (every SPACING texels) against anywhere else
seams() {
    $PY - "$@" <<'EOF'
import sys
import numpy as np
from osgeo import gdal
gdal.UseExceptions()
def rd(p):
    ds = gdal.Open(p)
    a = ds.GetRasterBand(1).ReadAsArray().astype(np.float64)
    ds = None
    return a
a, b, spacing, what = rd(sys.argv[1]), rd(sys.argv[2]), int(sys.argv[3]), sys.argv[4]
d = np.abs(a - b)
near = np.zeros(d.shape, bool)
for s in range(spacing, max(d.shape), spacing):
    near[:, max(s - 2, 0):s + 3] = True
    near[max(s - 2, 0):s + 3, :] = True
print("%s: seam max %.3g, elsewhere max %.3g, mean %.3g"
      % (what, d[near].max() if near.any() else 0.0, d[~near].max(), d.mean()))
EOF
}
HALO=$(awk -v r="$RADIUS" 'BEGIN {h = r / 10.0; printf "%d", (h == int(h) ? h : int(h) + 1) + 2}')
INNER=$((2048 - 2 * HALO))
seams "$C/tiled.tif" "$C/single.tif" "$INNER" "tiles of $INNER inner texels (halo $HALO)"
if [ -n "$TILE" ]; then
    run streamed "$TILE" HFS_GL_STRICT_LIMITS=0
    seams "$C/streamed.tif" "$C/single.tif" "$TILE" "streamed in windows of $TILE against one piece"
fi
