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
# cell) + 2).  Wall time and peak memory (RSS) of each run.  Needs
# python3-gdal and python3-numpy (installed with apt when missing: bench
# tools, not the product's).
# usage: tools/bench_gis_tiles.sh [BUILD] [WxH] [RADIUS_M] [DIRS]
set -euo pipefail
cd "$(dirname "$0")/.."
B=${1:-build}
SIZE=${2:-8192x6144}
RADIUS=${3:-500}
DIRS=${4:-8}
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
run() { # NAME ENV...: the svf, its wall time and peak RSS
    local name=$1
    shift
    env "$@" /usr/bin/time -f "$name: %e s, peak RSS %M KiB" "$H" svf "$C/dem.tif" \
        --radius "$RADIUS" --directions "$DIRS" -o "$C/$name.tif" 2>&1 | sed "s|$C/||"
}
run tiled HFS_GL_STRICT_LIMITS=1
run single HFS_GL_STRICT_LIMITS=0
$PY - "$C/tiled.tif" "$C/single.tif" "$RADIUS" <<'EOF'
import math, sys
import numpy as np
from osgeo import gdal
gdal.UseExceptions()
def rd(p):
    ds = gdal.Open(p)
    a = ds.GetRasterBand(1).ReadAsArray().astype(np.float64)
    ds = None
    return a
a, b = rd(sys.argv[1]), rd(sys.argv[2])
halo = math.ceil(float(sys.argv[3]) / 10.0) + 2
inner = 2048 - 2 * halo
d = np.abs(a - b)
near = np.zeros(d.shape, bool)
for s in range(inner, max(d.shape), inner):
    near[:, max(s - 2, 0):s + 3] = True
    near[max(s - 2, 0):s + 3, :] = True
print("tiles of %d inner texels (halo %d): seam max %.3g, elsewhere max %.3g, mean %.3g"
      % (inner, halo, d[near].max(), d[~near].max(), d.mean()))
EOF
