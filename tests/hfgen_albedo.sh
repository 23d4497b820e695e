#!/usr/bin/env bash
# hfgen albedo (tools/hfgen.c): the map of a field's heights is an RGB PFM
# of the field's size with every value in the documented range (0.07 to
# 0.42), darker below than above, and a render takes it as --albedo-map.
# usage: hfgen_albedo.sh HFGEN HFSHADE
set -euo pipefail
gen=$1 hfs=$2
d=$(mktemp -d)
trap 'rm -rf "$d"' EXIT
"$gen" cones --size 40x30 -o "$d/h.pfm"
"$gen" albedo "$d/h.pfm" -o "$d/a.pfm"
python3 - "$d/h.pfm" "$d/a.pfm" <<'PY'
import struct, sys
def rd(p):
    with open(p, 'rb') as f:
        t = f.readline().strip(); w, h = map(int, f.readline().split()); s = float(f.readline())
        n = w * h * (3 if t == b'PF' else 1)
        return t, w, h, struct.unpack(('<' if s < 0 else '>') + '%df' % n, f.read(4 * n))
th, w, h, z = rd(sys.argv[1])
ta, wa, ha, a = rd(sys.argv[2])
assert ta == b'PF' and (wa, ha) == (w, h), (ta, wa, ha)
assert all(0.069 <= v <= 0.421 for v in a), (min(a), max(a))
lo = min(range(w * h), key=lambda i: z[i]); hi = max(range(w * h), key=lambda i: z[i])
assert a[3 * lo + 1] < a[3 * hi + 1], 'not darker below than above'
PY
"$hfs" render --height "$d/h.pfm" --env-sh 3.5449077,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0 \
    --albedo-map "$d/a.pfm" --backend cpu --pfm "$d/o.pfm" --quiet
echo "hfgen albedo: RGB map of the field's size, in range, darker below; renders"
