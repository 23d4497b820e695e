#!/usr/bin/env bash
# The kiosk over a DEM larger than its display (issue 40 item 4; board/KIOSK.md
# "The map"): an N x N DEM (below) under the demo's sky and sun
# (data/demo.ini without its vertical exaggeration), on an x11 window of
# WxH under Xvfb, the GLES renderer (Mesa llvmpipe here), driven by a
# replay:
#   - from the whole field, a level in every WAIT_S seconds down to level 0
#     (each wait lets the kiosk light the next level's tiles ahead);
#   - then PANS pan steps of 4 detents (256 display pixels) east and south
#     in turn, WAIT_S seconds apart;
#   - a screenshot of the window (xwd, converted to PNG) after the last pan,
#     then a last step a level out.
# Reported from the --stats file: for each pan and zoom step, the tiles its
# frame rendered itself (0: the step is shown by its own frame, no stall),
# its render time and the tiles it showed from a coarser level (0: every
# tile was lit ahead); the tiles fetched ahead
# and their median render time; the cache's peak bytes and budget; the
# levels' bytes; the process's peak RSS (/usr/bin/time -v).
#
# usage: tools/bench_kiosk_map.sh BUILD_DIR [N] [WxH] [PANS] [WAIT_S] [OUT.png]
#        defaults 8192, 1024x600, 6, 30, kiosk-map.png
# Installs xvfb, x11-apps (xwd) and imagemagick (convert) when missing;
# needs python3-numpy (tools/install-deps.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
B=$(cd "$1" && pwd); N=${2:-8192}; SIZE=${3:-1024x600}
PANS=${4:-6}; WAIT=${5:-30}; PIC=${6:-kiosk-map.png}
case "$PIC" in /*) ;; *) PIC=$PWD/$PIC ;; esac
need() { command -v "$1" >/dev/null || { echo "bench_kiosk_map: installing $2"; \
    ${SUDO:-$( [ "$(id -u)" = 0 ] || echo sudo)} apt-get install -y "$2" >/dev/null; }; }
need Xvfb xvfb; need xwd x11-apps
dpkg -s imagemagick >/dev/null 2>&1 || need /usr/bin/convert imagemagick
T=$(mktemp -d); trap 'kill $XPID 2>/dev/null; rm -rf "$T"' EXIT
XPID=
# The DEM: data/jacksboro.png (403x344, 83 m cells, 840 m of relief: a real
# ridge-and-valley landscape) mirrored into N x N, so that every seam is
# continuous terrain.
"$B/tools/hfgen" crop data/jacksboro.png --rect 0,0,403,344 -o "$T/j.pfm" >/dev/null
/usr/bin/python3 - "$T/j.pfm" "$T/dem.pfm" "$N" <<'EOF'
import numpy, sys
f = open(sys.argv[1], 'rb'); f.readline(); w, h = map(int, f.readline().split())
s = float(f.readline())
a = numpy.fromfile(f, dtype='<f4' if s < 0 else '>f4', count=w * h).reshape(h, w)
n = int(sys.argv[3])
m = numpy.block([[a, a[:, ::-1]], [a[::-1, :], a[::-1, ::-1]]])  # 2w x 2h, continuous
z = numpy.tile(m, (n // m.shape[0] + 1, n // m.shape[1] + 1))[:n, :n].astype('<f4')
with open(sys.argv[2], 'wb') as o:
    o.write(b'Pf\n%d %d\n-1.0\n' % (n, n))
    z.tofile(o)
EOF
cat > "$T/scene.ini" <<EOS
height = dem.pfm
dx = 83
env-map = $PWD/data/courtyard.exr
key = 336,15,2,1500
albedo = 0.35
EOS
cp board/kiosk-map.ini "$T/knobs.ini" # the example's knobs: px, py, zoom
W=${SIZE%x*}; H=${SIZE#*x}
LEVELS=1; w=$N
while [ "$w" -gt "$W" ] || [ "$w" -gt "$H" ]; do w=$(((w + 1) / 2)); LEVELS=$((LEVELS + 1)); done
t=$((WAIT * 1000)); : > "$T/replay.txt"
for ((l = 1; l < LEVELS; ++l)); do echo "$t zoom turn 1" >> "$T/replay.txt"; t=$((t + WAIT * 1000)); done
for ((p = 0; p < PANS; ++p)); do
    [ $((p % 2)) = 0 ] && k=px || k=py
    echo "$t $k turn 4" >> "$T/replay.txt"; t=$((t + WAIT * 1000))
done
SHOT=$((t / 1000 - WAIT / 2))
echo "$t zoom turn -1" >> "$T/replay.txt" # the end, after the screenshot: a level out
D=:$((90 + RANDOM % 9))
Xvfb "$D" -screen 0 "${W}x${H}x24" -nolisten tcp 2>/dev/null & XPID=$!
sleep 1
( sleep "$SHOT"; DISPLAY=$D xwd -root -silent > "$T/shot.xwd" 2>/dev/null ) &
SHOTPID=$!
cd "$T"
echo "bench_kiosk_map: ${N}x${N} DEM (Jacksboro mirrored, 83 m cells), ${W}x${H} on Xvfb," \
     "$LEVELS levels, $PANS pans, ${WAIT} s apart ($((t / 1000)) s)"
DISPLAY=$D /usr/bin/time -v "$B/board/hfshade-kiosk" scene.ini --input knobs.ini --no-devices \
    --replay replay.txt --exit-after-replay --display x11 --size "$SIZE" --stats st.txt \
    2> log.txt || { cat log.txt; exit 1; }
wait $SHOTPID || true
[ -s shot.xwd ] && /usr/bin/convert xwd:shot.xwd "$PIC" && echo "picture: $PIC"
grep -E "started|error|warn" log.txt | sed 's/^/  /' || true
python3 - st.txt log.txt <<'EOF'
import statistics, sys
lines = [l.split() for l in open(sys.argv[1]) if not l.startswith('#')]
frames, maps, events, pre = {}, {}, {}, []
for l in lines:
    if l[0] == 'frame': frames[int(l[1])] = float(l[3])
    elif l[0] == 'map': maps[int(l[1])] = l
    elif l[0] == 'event' and l[4] != '-1': events.setdefault(int(l[4]), []).append(l[6])
    elif l[0] == 'prefetch': pre.append(float(l[3]))
def steps(controls):
    return [(f, int(maps[f][2]), int(maps[f][5]), frames[f], int(maps[f][10]))
            for f in sorted(events) if any(c in controls for c in events[f])]
for name, controls in (('zoom', ('zoom',)), ('pan', ('px', 'py'))):
    rows = steps(controls)
    print('%s steps (frame, level, tiles its frame rendered, render ms, tiles shown coarse):'
          % name)
    for f, lev, r, ms, c in rows:
        print('  %4d  L%d  %3d  %9.1f  %3d' % (f, lev, r, ms, c))
    if rows:
        print('  %d steps, %d shown by their own frame with no tile to render (no stall), %d of'
              ' them all lit; render ms median %.1f, max %.1f' % (
                  len(rows), sum(1 for r in rows if r[2] == 0),
                  sum(1 for r in rows if r[2] == 0 and r[4] == 0),
                  statistics.median([r[3] for r in rows]), max(r[3] for r in rows)))
print('tiles fetched ahead: %d, median %.0f ms a tile' % (len(pre), statistics.median(pre) if pre else 0))
peak = max(int(m[7]) for m in maps.values())
budget = max(int(m[8]) for m in maps.values())
lv = max(int(m[9]) for m in maps.values())
print('cache: peak %.1f MB of a %.1f MB budget; levels above 0: %.1f MB' % (peak / 2**20, budget / 2**20, lv / 2**20))
for l in open(sys.argv[2]):
    if 'Maximum resident set size' in l:
        print('peak RSS: %.0f MB' % (int(l.split()[-1]) / 1024))
EOF
