#!/bin/bash
# kiosk_capture_loss.sh KIOSK PRELOAD HFGEN — a camera unplugged under a
# running hfshade-kiosk: the fake V4L2 device (capture_fake.c) behind the
# C library's calls (capture_preload.c, LD_PRELOAD) streams a moving
# block, vanishes at frame 20 (ENODEV to everything, open included) and
# returns 400 ms later.  The kiosk must survive: one warning for the loss,
# none for the failed reopens (same reason), one "back" line, frames
# (heights) before and after, exit 0 on SIGTERM.  Then the same for a sky
# camera (role = environment, the same frames read as YUYV): "sky" frames
# (lighting) before and after, the same single warning and "back".
# 77 when the kiosk has no GLES context.
set -u
KIOSK=$1 PRELOAD=$2 HFGEN=$3
T=$(mktemp -d)
trap 'kill $pid 2>/dev/null; rm -rf "$T"' EXIT
cd "$T" || exit 1
fail() { echo "FAIL: $*"; echo "--- log"; cat log.txt; exit 1; }
"$HFGEN" flat --size 64x48 -o flat.pfm >/dev/null || fail hfgen
printf 'height = flat.pfm\ndx = 0.004\nzscale = 1\nkey = 300,30,2,3\nalbedo = 0.6\nbackend = gles\n' > scene.ini
# run KIND CONFIG: the kiosk on CONFIG's camera, unplugged at frame 20;
# KIND: the stats lines of its frames ("capture" or "sky").
run() {
    kind=$1
    printf "$2" > cap.ini
    # ASan (sanitizer builds) must accept a library preloaded before it.
    HFS_FAKE_GONE_AT=20 HFS_FAKE_GONE_MS=400 LD_PRELOAD="$PRELOAD" \
    ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}verify_asan_link_order=0" \
        "$KIOSK" scene.ini --input cap.ini --display headless --stats st.txt 2> log.txt &
    pid=$!
    # Until frames after the loss are shown (sequence numbers past 30), at most 120 s.
    for _ in $(seq 1200); do
        kill -0 $pid 2>/dev/null || break
        awk -v kind="$kind" '$1 == kind && $2 > 30 { found = 1 } END { exit !found }' st.txt 2>/dev/null && break
        sleep 0.1
    done
    if ! kill -0 $pid 2>/dev/null; then
        wait $pid; rc=$?
        grep -q -i "gles\|egl\|context" log.txt && ! grep -q started log.txt &&
            { echo "no GLES context: skipped"; cat log.txt; exit 77; }
        fail "the kiosk ended (exit $rc)"
    fi
    kill -TERM $pid; wait $pid; rc=$?; pid=
    [ $rc -eq 0 ] || fail "exit $rc after SIGTERM"
    n_lost=$(grep -c 'video /dev/video-fake: VIDIOC_DQBUF: No such device (showing the last frame; retrying)' log.txt)
    n_back=$(grep -c 'video /dev/video-fake: back' log.txt)
    n_warn=$(grep -c -i 'warning\|<4>\|No such device' log.txt)
    [ "$n_lost" -eq 1 ] || fail "$kind: loss reported $n_lost times"
    [ "$n_back" -eq 1 ] || fail "$kind: back reported $n_back times"
    [ "$n_warn" -eq 1 ] || fail "$n_warn lines about the loss (the failed reopens must stay quiet)"
    before=$(awk -v kind="$kind" '$1 == kind && $2 < 20' st.txt | wc -l)
    after=$(awk -v kind="$kind" '$1 == kind && $2 > 20' st.txt | wc -l)
    [ "$before" -ge 5 ] || fail "$kind: only $before frames before the loss"
    [ "$after" -ge 3 ] || fail "$kind: only $after frames after the device came back"
    grep -v "^hfshade-kiosk: started" log.txt | head -5
    grep -qi "nan\|inf" st.txt && fail "$kind: a NaN or Inf in the stats"
    echo "$kind: $before frames before the loss, $after after"
}
run capture '[capture cam]\ndevice = /dev/video-fake\nformat = Z16\nsize = 320x240\nrate = 30\n'
run sky '[capture sky]\ndevice = /dev/video-fake\nformat = YUYV\nsize = 320x240\nrate = 30\nrole = environment\nenv_lights = auto\n'
echo "kiosk_capture_loss: ok"
