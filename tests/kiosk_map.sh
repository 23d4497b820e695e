#!/bin/bash
# kiosk_map.sh KIOSK HFGEN — hfshade-kiosk showing a field larger than its
# display as a map (board/kiosk_map.h, board/KIOSK.md "The map"), headless
# with --size, knobs replayed, on the CPU reference (no GL needed):
#   - the first frame shows the whole field (the coarsest level), centred;
#   - map.zoom turns to level 0, map.pan_x / map.pan_y move the centre by
#     step x 2^level texels, kept on the field; each frame's "map" stats
#     line says so, and a pan shows other terrain;
#   - while the kiosk is idle it lights tiles ahead of the view ("prefetch"
#     lines), and the cache never holds more than its budget;
#   - a knob of a map with no map (a field that fits): nothing moves.
set -u
KIOSK=$1 HFGEN=$2
KNOBS=$(cd "$(dirname "$0")/.." && pwd)/board/kiosk-map.ini # the example's knobs
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
cd "$T" || exit 1
fail() { echo "FAIL: $*"; exit 1; }
"$HFGEN" fractal --size 512x256 --relief 0.12 --hurst 0.3 --seed 3 -o dem.pfm >/dev/null || fail hfgen
printf 'height = dem.pfm\ndx = 30\nkey = 120,12,1,20\nenv-sh = %s\nbackend = cpu\npreset = headless\nnphi-env = 4\nnphi-key = 1\n' \
    3.5449077,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0 > scene.ini
# 0 s: three levels in (to level 0); 0.5 s: a detent east (64 texels);
# idle 4 s (tiles ahead); then 2 detents south (128 texels: kept on the
# field, 256 tall) and far east (kept too), then out a level.
printf '0 zoom turn 3\n500 px turn 1\n4500 py turn 2\n4600 px turn 40\n5000 zoom turn -1\n' \
    > replay.txt
"$KIOSK" scene.ini --input "$KNOBS" --no-devices --replay replay.txt --exit-after-replay \
    --display headless --size 96x64 --out 'f-%03d.png' --stats st.txt 2> log.txt ||
    { cat log.txt; fail "kiosk exit"; }
# map N LEVEL X Y RENDERED CACHED BYTES BUDGET LEVEL_BYTES, one per frame
grep '^map ' st.txt > map.txt
expect() { # frame level x y
    awk -v n="$1" -v l="$2" -v x="$3" -v y="$4" \
        '$2 == n { found = 1; if ($3 != l || $4 != x || $5 != y) { print "frame " n ": " $0; exit 1 } }
         END { exit !found }' map.txt || fail "frame $1 not at level $2 ($3, $4): $(cat map.txt)"
}
expect 0 3 256.0 128.0 # 512x256 -> 256x128 -> 128x64 -> 64x32 fits 96x64: 4 levels
expect 1 0 256.0 128.0
expect 2 0 320.0 128.0
n=$(wc -l < map.txt)
[ "$n" -ge 4 ] || fail "$n map lines"
tail -1 map.txt | awk '{ exit !($3 == 1 && $4 == 512.0 && $5 == 256.0) }' ||
    fail "last frame not level 1 at (512, 256): $(tail -1 map.txt)"
awk '$1 == "map" && $8 > $9 { exit 1 }' st.txt || fail "the cache over its budget: $(cat map.txt)"
grep -q '^prefetch ' st.txt || fail "no tile fetched ahead in 4 s idle"
# pictures on the 96x64 canvas; the pan shows other terrain
size() { python3 -c "import struct,sys;d=open(sys.argv[1],'rb').read(24);print(*struct.unpack('>II',d[16:24]))" "$1"; }
for f in f-000.png f-001.png f-002.png; do
    [ "$(size $f)" = "96 64" ] || fail "$f: $(size $f)"
done
! cmp -s f-001.png f-002.png || fail "the pan east shows the same picture"
# a field that fits the display: no map, the knobs move nothing
"$KIOSK" scene.ini --input "$KNOBS" --no-devices --replay replay.txt --exit-after-replay \
    --display headless --size 600x300 --stats st2.txt 2> log2.txt || { cat log2.txt; fail "fits"; }
! grep -q '^map ' st2.txt || fail "a map for a field that fits"
[ "$(grep -c '^frame ' st2.txt)" -eq 1 ] || fail "knobs moved a map that is not there"
echo "PASS: $(cat map.txt | tr '\n' ';')"
