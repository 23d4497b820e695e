#!/usr/bin/env bash
# The kiosk on an x11 window (one Xvfb, xvfb-run) with its two paths to the
# screen (issue 20): by default the renderer shares the window's EGL
# context and grid frames go to the screen as its texture, with --readback
# they are read back and uploaded.  The same replay (key-light turns, an
# overlay toggle on and off, which takes the read-back path for its
# frames and comes back) must run to its end in both, exit 0, show every
# event, and the log must say which path was taken.  That the texture shows
# the read-back picture's bytes is test_display_x11's "texture" check.
# Exit 77 without xvfb-run (or when the kiosk cannot open a GL window).
# usage: kiosk_x11_texture.sh KIOSK HFGEN
set -u
KIOSK=$1 HFGEN=$2
command -v xvfb-run >/dev/null || { echo "SKIP: xvfb-run is not installed"; exit 77; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$HFGEN" cones --size 64x48 -o "$tmp/cones.pfm" >/dev/null || { echo "FAIL: hfgen"; exit 1; }
printf 'height = cones.pfm\nenv-sh = 1,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0\nkey = 30,20,3,200\n' \
    >"$tmp/scene.ini"
printf '[knob az]\naction = key.azimuth\nstep = 10\n[button ov]\naction = overlay.toggle\n' \
    >"$tmp/cfg.ini"
printf '100 az turn 1\n200 az turn 1\n300 ov press\n400 az turn 1\n500 ov press\n600 az turn 1\n' \
    >"$tmp/replay.txt"
fail=0
for mode in texture readback; do
    flag=; [ $mode = readback ] && flag=--readback
    xvfb-run -a -s "-screen 0 320x240x24" "$KIOSK" "$tmp/scene.ini" --input "$tmp/cfg.ini" \
        --replay "$tmp/replay.txt" --display x11 --size 64x48 --stats "$tmp/$mode.txt" \
        --exit-after-replay $flag >"$tmp/$mode.out" 2>"$tmp/$mode.log"
    rc=$?
    if [ $rc != 0 ] && grep -q "display x11:" "$tmp/$mode.log"; then
        echo "SKIP: no GL window here: $(grep -m1 "display x11:" "$tmp/$mode.log")"; exit 77
    fi
    # Sanitizer builds: with the texture path the window's EGL display is
    # the only one, so eglTerminate at exit unloads Mesa's driver and what
    # its globals still point to shows as a leak whose frames past the
    # allocator lie in no module any more: "<unknown module>", or, once the
    # addresses are mapped again, a system library's name (.ci/run's ASan
    # suite saw libubsan's) (with dlclose made a no-op nothing is
    # reported).  A leak with any frame of ours (a frame naming a source
    # file or one of our binaries, not a system library) still fails.
    if [ $rc != 0 ] && grep -q "ERROR: LeakSanitizer" "$tmp/$mode.log" &&
        ! grep -E '^ +#[1-9][0-9]* 0x' "$tmp/$mode.log" |
            grep -Evq '\((<unknown module>|/usr/lib/[^)]*|/lib/[^)]*)\)$'; then
        echo "note [$mode]: $(grep -m1 SUMMARY "$tmp/$mode.log") (Mesa's unloaded driver only)"
        rc=0
    fi
    [ $rc = 0 ] || { echo "FAIL [$mode]: exit $rc: $(cat "$tmp/$mode.log")"; fail=1; continue; }
    shown=$(awk '$1 == "event" && $6 == 1 && $3 > 0' "$tmp/$mode.txt" | wc -l)
    [ "$shown" = 6 ] || { echo "FAIL [$mode]: $shown of 6 events shown"; fail=1; }
    sharing=0; grep -q "frames as textures" "$tmp/$mode.log" && sharing=1
    want=1; [ $mode = readback ] && want=0
    [ $sharing = $want ] || { echo "FAIL [$mode]: the log says sharing=$sharing"; fail=1; }
    echo "ok   [$mode] $(grep -o 'renderer [^,]*' "$tmp/$mode.log"), $shown events shown"
done
exit $fail
