#!/usr/bin/env bash
# A lit frame larger than the device holds, in tiles (issue 39 item 1;
# runtime/renderer/tiled_render.h): an `hfgen fractal` field of WxH (default
# 8192x6144) at texel spacing DX (default 100: its relief over dx sizes the
# halo), a uniform SH sky and a 2-degree sun 15 degrees up, rendered by
# `hfshade render` (GLES defaults) twice: under HFS_GL_STRICT_LIMITS=1
# (tiles of at most 2048 texels) and at the driver's own limit (one frame up
# to 4096 texels a side, HFS_GLES_MAX_FRAME_SIDE; tiles of 4096 beyond);
# SPEC's metrics of the one against the other (`hfshade compare`), and the
# seam measure: the largest difference (of the second's maximum) at the
# texels within 2 of a seam of the strict tiling against anywhere else.
# usage: tools/bench_tiled_render.sh [BUILD] [WxH] [DX]
set -euo pipefail
cd "$(dirname "$0")/.."
B=${1:-build}
SIZE=${2:-8192x6144}
DX=${3:-100}
C=$(mktemp -d)
trap 'rm -rf "$C"' EXIT
"$B/tools/hfgen" fractal --size "$SIZE" -o "$C/f.pfm"
SCENE="--height $C/f.pfm --dx $DX --env-sh 3.5449077,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0 --key 336,15,2,3"
# shellcheck disable=SC2086 # SCENE's flags are words
{
    HFS_GL_STRICT_LIMITS=1 /usr/bin/time -f "strict: %e s, peak RSS %M KiB" \
        "$B/tools/hfshade" render $SCENE --pfm "$C/strict.pfm"
    /usr/bin/time -f "driver: %e s, peak RSS %M KiB" "$B/tools/hfshade" render $SCENE \
        --pfm "$C/driver.pfm"
    "$B/tools/hfshade" compare $SCENE "$C/strict.pfm" "$C/driver.pfm"
} 2>&1 | sed "s|$C/||g"
/usr/bin/python3 -c "import numpy" 2>/dev/null ||
    DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends python3-numpy >&2
/usr/bin/python3 - "$C/f.pfm" "$C/strict.pfm" "$C/driver.pfm" "$DX" <<'EOF'
import math, sys
import numpy as np
def read(p):
    with open(p, "rb") as f:
        kind = f.readline().strip()
        w, h = (int(v) for v in f.readline().split())
        scale = float(f.readline())
        a = np.frombuffer(f.read(), dtype="<f4" if scale < 0 else ">f4")
    return a.reshape(h, w, -1).astype(np.float64)
z, a, b = read(sys.argv[1]), read(sys.argv[2]), read(sys.argv[3])
dx = float(sys.argv[4])
eps = min(0.02216, math.radians(15.0 - 2.0))    # tiled_render.h: the sky's, the sun's lowest edge
halo = math.ceil((z.max() - z.min()) / (dx * math.tan(eps))) + 2
halo = (halo + 15) // 16 * 16
inner = (2048 - 2 * halo) // 16 * 16
d = np.abs(a - b).max(axis=2) / b.max()
near = np.zeros(d.shape, bool)
for s in range(inner, max(d.shape), inner):
    near[:, max(s - 2, 0):s + 3] = True
    near[max(s - 2, 0):s + 3, :] = True
print("strict tiles of %d inner texels (halo %d): seam max %.3g, elsewhere max %.3g"
      % (inner, halo, d[near].max(), d[~near].max()))
EOF
