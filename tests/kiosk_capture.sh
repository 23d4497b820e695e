#!/bin/bash
# kiosk_capture.sh KIOSK SYNTH HFGEN — hfshade-kiosk with a [capture NAME]
# section replaying a synthetic depth recording (docs/CAPTURE.md):
#   - every frame is shown (one "capture" stats line per frame that changed
#     the heights), frames differ once the hand is in, exit 0 at the end;
#   - a frame file broken mid-stream: one warning naming it, the kiosk
#     goes on showing the last good heights and the frames after it;
#   - --capture-record writes a recording that replays the same frames;
#   - configuration errors are file:line: problem (a sky section given a
#     depth recording's format; a missing recording).
# 77 when the kiosk has no GLES context (as the other kiosk GL tests).
set -u
KIOSK=$1 SYNTH=$2 HFGEN=$3
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
cd "$T" || exit 1
fail() { echo "FAIL: $*"; exit 1; }
"$HFGEN" flat --size 64x48 -o flat.pfm >/dev/null || fail hfgen
printf 'height = flat.pfm\ndx = 0.004\nzscale = 1\nkey = 300,30,2,3\nalbedo = 0.6\nbackend = gles\n' > scene.ini
"$SYNTH" rec --size 128x96 --frames 40 --hand 10,20,30 >/dev/null || fail synth
printf '[capture sand]\nreplay = rec\nrole = heights\n' > cap.ini
"$KIOSK" scene.ini --input cap.ini --display headless --exit-after-capture --stats st.txt \
    --out 'f-%03d.png' --capture-record rec2 2> log.txt
rc=$?
if [ $rc -ne 0 ] && grep -q -i "gles\|egl\|context" log.txt; then
    echo "no GLES context: skipped"; cat log.txt; exit 77
fi
[ $rc -eq 0 ] || { cat log.txt; fail "kiosk exit $rc"; }
n=$(grep -c '^capture ' st.txt)
# 40 frames at 30 fps; a slow frame makes the replay skip to the newest:
# at least half must be shown (measured: 38-40 on llvmpipe).
[ "$n" -ge 20 ] || fail "only $n capture frames shown"
cmp -s f-000.png f-020.png && fail "the hand frame equals the first frame"
grep -q 'capture replay finished' log.txt || fail "no end message"
[ "$(grep -c '^frame ' rec2/capture.txt)" -ge 20 ] || fail "--capture-record wrote too few frames"
"$KIOSK" scene.ini --input cap.ini --display headless --exit-after-capture \
    --capture-record rec2 2> log2.txt && fail "recording over an old one accepted"
grep -q 'rec2: already holds a recording' log2.txt || fail "$(cat log2.txt)"

# A frame file broken mid-stream.
truncate -s 100 rec/frame-000015.raw
"$KIOSK" scene.ini --input cap.ini --display headless --exit-after-capture --stats st3.txt \
    2> log3.txt || { cat log3.txt; fail "broken frame was fatal"; }
[ "$(grep -c 'frame-000015.raw: too short' log3.txt)" -eq 1 ] || { cat log3.txt; fail "warning"; }
[ "$(grep -c '^capture ' st3.txt)" -ge 20 ] || fail "frames after the broken one not shown"

# Configuration errors.
printf '[capture env]\nreplay = rec\nrole = environment\nformat = Y16\n' > env.ini
"$KIOSK" scene.ini --input env.ini --check 2> e.txt && fail "environment of depth accepted"
grep -q 'env.ini:4: format: role environment needs colour or grey' e.txt || fail "$(cat e.txt)"
printf '[capture a]\nreplay = none\n' > miss.ini
"$KIOSK" scene.ini --input miss.ini --display headless 2> m.txt && fail "missing recording"
grep -q 'none/capture.txt' m.txt || fail "$(cat m.txt)"
printf '[capture a]\ndevice = /dev/video0\nreplay = rec\n' > both.ini
"$KIOSK" scene.ini --input both.ini --check 2> b.txt && fail "device and replay"
grep -q 'both.ini:3: \[capture a\]: give device = PATH or replay = DIR' b.txt || fail "$(cat b.txt)"
echo "kiosk_capture: ok ($n frames shown)"
