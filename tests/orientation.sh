#!/usr/bin/env bash
# orientation.sh — one orientation everywhere (SPEC "Orientation", issue 14):
# an asymmetric field rendered by `hfshade render -o` and shown by the
# kiosk's headless display (--out) must be the same picture, row j = 0 at
# the top of both.  (Before the fix the kiosk showed it upside down.)
# usage: orientation.sh HFSHADE HFGEN KIOSK PNG_SAME_PICTURE
set -u
HFSHADE=$1 HFGEN=$2 KIOSK=$3 SAME=$4
w=$(mktemp -d)
trap 'rm -rf "$w"' EXIT
"$HFGEN" cones --size 40x28 -o "$w/h.pfm" >/dev/null || { echo "FAIL: hfgen"; exit 1; }
# A light near row 0 and a low sun from +y: nothing about the picture is
# symmetric north-south.
printf 'height = h.pfm\nbackend = cpu\nkey = 90,20,2,8\nlocal = 6,4,8,1.5,120\nalbedo = 0.8\n' >"$w/s.ini"
: >"$w/none.txt"
"$HFSHADE" render "$w/s.ini" -o "$w/render.png" --quiet || { echo "FAIL: render"; exit 1; }
"$SAME" --asymmetric "$w/render.png" || { echo "FAIL: the test picture is symmetric"; exit 1; }
"$KIOSK" "$w/s.ini" --display headless --out "$w/frame-%02d.png" --replay "$w/none.txt" \
    --exit-after-replay 2>"$w/log" || { echo "FAIL: kiosk"; cat "$w/log"; exit 1; }
"$SAME" "$w/render.png" "$w/frame-00.png" || { echo "FAIL: the kiosk shows another picture"; exit 1; }
echo PASS
