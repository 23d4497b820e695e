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
# With TILE as `only:N` (a DEM too large for one piece: 16384x16384 needs
# about 16 GB whole) only the streamed run is made, in windows of N, and
# checked against a crop of the DEM computed whole: the crop of 2048 texels
# plus the halo around the DEM's centre, its inner 2048^2 against the same
# texels of the streamed raster (the seam measure, a window seam crossing
# the crop).
# usage: tools/bench_gis_tiles.sh [BUILD] [WxH] [RADIUS_M] [DIRS] [TILE]
#   e.g. tools/bench_gis_tiles.sh build 4096x3072 300 4 1024
#        tools/bench_gis_tiles.sh build 16384x16384 500 8 only:2048
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
$PY tools/bench_dem.py "$C/f.pfm" "$C/dem.tif" 10
run() { # NAME TILE ENV...: the svf, its wall time and peak RSS
    local name=$1 tile=$2
    shift 2
    env "$@" /usr/bin/time -f "$name: %e s, peak RSS %M KiB" "$H" svf "$C/dem.tif" \
        --radius "$RADIUS" --directions "$DIRS" --tile "$tile" -o "$C/$name.tif" 2>&1 |
        sed "s|$C/||"
}
if [[ "$TILE" =~ ^only:([0-9]+)$ ]]; then
    run streamed "${BASH_REMATCH[1]}" HFS_GL_STRICT_LIMITS=0
    read -r W Hh < <(echo "$SIZE" | tr x ' ')
    HALO=$(awk -v r="$RADIUS" 'BEGIN {h = r / 10.0; printf "%d", (h == int(h) ? h : int(h) + 1) + 2}')
    X0=$((W / 2 - 1024 - HALO)) Y0=$((Hh / 2 - 1024 - HALO)) S=$((2048 + 2 * HALO))
    gdal_translate -q -srcwin "$X0" "$Y0" "$S" "$S" "$C/dem.tif" "$C/crop.tif"
    "$H" svf "$C/crop.tif" --radius "$RADIUS" --directions "$DIRS" --tile 0 --quiet \
        -o "$C/crop_svf.tif"
    $PY - "$C/streamed.tif" "$C/crop_svf.tif" "$X0" "$Y0" "$HALO" "${BASH_REMATCH[1]}" <<'EOF'
import sys
import numpy as np
from osgeo import gdal
gdal.UseExceptions()
x0, y0, halo, tile = (int(v) for v in sys.argv[3:7])
ds = gdal.Open(sys.argv[1])
a = ds.GetRasterBand(1).ReadAsArray(x0 + halo, y0 + halo, 2048, 2048).astype(np.float64)
ds = None
ds = gdal.Open(sys.argv[2])
b = ds.GetRasterBand(1).ReadAsArray(halo, halo, 2048, 2048).astype(np.float64)
ds = None
d = np.abs(a - b)
near = np.zeros(d.shape, bool)  # the streamed windows' seams inside the crop
for axis, o in ((1, x0 + halo), (0, y0 + halo)):
    for s in range((o // tile + 1) * tile, o + 2048, tile):
        k = s - o
        if axis == 1:
            near[:, max(k - 2, 0):k + 3] = True
        else:
            near[max(k - 2, 0):k + 3, :] = True
print("streamed against the centre crop computed whole: mean %.3g, seam max %.3g, "
      "elsewhere max %.3g" % (d.mean(), d[near].max() if near.any() else 0.0, d[~near].max()))
EOF
    exit 0
fi
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
