#!/usr/bin/env bash
# Bad input to hfshade-kiosk: every case must exit non-zero (2 for usage,
# 1 otherwise) without a signal, with ONE line on stderr that names the
# input, and must not have opened the display (no frame written).  Needs no
# GL: every case fails before the renderer is made.  The shipped example
# (data/demo.ini + board/kiosk.ini) passes --check.
# usage: kiosk_bad_inputs.sh KIOSK HFGEN SOURCE_DIR
set -u
KIOSK=$1 HFGEN=$2 SRC=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fails=0 cases=0

"$HFGEN" flat --size 16x12 -o "$tmp/flat.pfm" >/dev/null || { echo "FAIL: hfgen"; exit 1; }
printf 'height = flat.pfm\nenv-sh = 1,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0\nkey = 30,20,3,1\n' >"$tmp/ok.ini"
printf '[knob az]\naction = key.azimuth\n' >"$tmp/ok_cfg.ini"
printf '100 az turn 1\n' >"$tmp/ok_replay.txt"

# expect_fail NAME STATUS NEEDLE ARGS... : exit STATUS, NEEDLE in the line.
expect_fail() {
    local name=$1 want=$2 needle=$3; shift 3
    cases=$((cases + 1))
    rm -f "$tmp"/f-*.png
    "$KIOSK" "$@" >"$tmp/stdout" 2>"$tmp/stderr"
    local rc=$? lines
    lines=$(wc -l <"$tmp/stderr")
    if [ $rc -ne "$want" ]; then
        echo "FAIL [$name]: exit status $rc, want $want: $(cat "$tmp/stderr")"; fails=$((fails + 1)); return
    fi
    if [ "$lines" -ne 1 ]; then
        echo "FAIL [$name]: $lines lines on stderr:"; cat "$tmp/stderr"; fails=$((fails + 1)); return
    fi
    if ! grep -qF -- "$needle" "$tmp/stderr"; then
        echo "FAIL [$name]: message lacks '$needle': $(cat "$tmp/stderr")"; fails=$((fails + 1)); return
    fi
    if ls "$tmp"/f-*.png >/dev/null 2>&1; then
        echo "FAIL [$name]: a frame was written"; fails=$((fails + 1)); return
    fi
    echo "ok   [$name] $(cat "$tmp/stderr")"
}

H=(--display headless --out "$tmp/f-%d.png")
expect_fail missing-scene 1 "nope.ini" "$tmp/nope.ini" "${H[@]}"
printf 'height = flat.pfm\nk = 99\n' >"$tmp/bad.ini"
expect_fail broken-scene 1 "bad.ini:2: k: 99" "$tmp/bad.ini" "${H[@]}"
printf 'env-sh = 1,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0\n' >"$tmp/noheight.ini"
expect_fail scene-no-height 1 "noheight.ini" "$tmp/noheight.ini" "${H[@]}"
printf 'height = gone.pfm\n' >"$tmp/gone.ini"
expect_fail scene-missing-height 1 "gone.pfm" "$tmp/gone.ini" "${H[@]}"
expect_fail missing-config 1 "nope_cfg.ini" "$tmp/ok.ini" --input "$tmp/nope_cfg.ini" "${H[@]}"
printf '[knob az]\naction = key.azimut\n' >"$tmp/bad_cfg.ini"
expect_fail broken-config 1 "bad_cfg.ini:2: unknown action 'key.azimut'" "$tmp/ok.ini" --input "$tmp/bad_cfg.ini" "${H[@]}"
printf '[knob az]\naction = key.azimuth\nlight = 3\n' >"$tmp/light_cfg.ini"
expect_fail config-light-missing 1 "light_cfg.ini: az: light 3: the scene has 1 key light" "$tmp/ok.ini" --input "$tmp/light_cfg.ini" "${H[@]}"
printf '[knob az]\ngpio = hfs-no-such-chip:1,2\naction = key.azimuth\n' >"$tmp/dev_cfg.ini"
expect_fail config-device-missing 1 "dev_cfg.ini: gpio hfs-no-such-chip" "$tmp/ok.ini" --input "$tmp/dev_cfg.ini" "${H[@]}"
printf '[button ok]\nevdev = /nonexistent/event9:KEY_ENTER\naction = overlay.toggle\n' >"$tmp/evdev_cfg.ini"
expect_fail config-evdev-missing 1 "evdev_cfg.ini: evdev /nonexistent/event9" "$tmp/ok.ini" --input "$tmp/evdev_cfg.ini" "${H[@]}"
expect_fail unknown-display 1 'display "foo"' "$tmp/ok.ini" --display foo
printf '100 az spin 1\n' >"$tmp/bad_replay.txt"
expect_fail broken-replay 1 "bad_replay.txt:1:" "$tmp/ok.ini" --input "$tmp/ok_cfg.ini" --replay "$tmp/bad_replay.txt" "${H[@]}"
expect_fail missing-replay 1 "nope_replay.txt" "$tmp/ok.ini" --replay "$tmp/nope_replay.txt" "${H[@]}"
expect_fail bad-stats-path 1 "/nonexistent-dir/stats.txt" "$tmp/ok.ini" --stats /nonexistent-dir/stats.txt "${H[@]}"
expect_fail unknown-option 2 "--bogus" "$tmp/ok.ini" --bogus
expect_fail no-scene 2 "no scene file" --display headless
expect_fail missing-value 2 "--input" "$tmp/ok.ini" --input
expect_fail bad-size 2 "--size" "$tmp/ok.ini" --size 0x3
expect_fail bad-exposure 2 "--exposure" "$tmp/ok.ini" --exposure -41
expect_fail out-not-headless 2 "--out" "$tmp/ok.ini" --display x11 --out "$tmp/f-%d.png"
expect_fail exit-without-replay 2 "--exit-after-replay" "$tmp/ok.ini" --exit-after-replay

# The shipped example loads and fits the demo scene.
cases=$((cases + 1))
if out=$("$KIOSK" "$SRC/data/demo.ini" --input "$SRC/board/kiosk.ini" \
         --replay "$SRC/tests/data/kiosk/example_replay.txt" --check 2>&1); then
    echo "ok   [example-check] $out"
else
    echo "FAIL [example-check]: $out"; fails=$((fails + 1))
fi

echo "$((cases - fails))/$cases cases passed"
[ $fails -eq 0 ]
