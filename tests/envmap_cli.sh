#!/usr/bin/env bash
# hfshade envmap decompose and hfgen sky end to end (issue 17): a generated
# sky's sun found where hfgen put it; the printed lines parse as a scene
# (rendered with --check); the picture written; bad maps and options give
# one line on stderr naming the input, a non-zero exit and no picture.
# usage: envmap_cli.sh HFSHADE HFGEN
set -u
HFSHADE=$1 HFGEN=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fails=0
fail() { echo "FAIL: $*"; fails=$((fails + 1)); }

"$HFGEN" sky --size 256x128 --sun 200,25 --sun-diameter 2 --share 0.7 -o "$tmp/sky.pfm" ||
    fail "hfgen sky"
"$HFGEN" flat --size 16x12 -o "$tmp/flat.pfm" || fail "hfgen flat"
"$HFSHADE" envmap decompose "$tmp/sky.pfm" --picture "$tmp/sky.png" >"$tmp/out" 2>"$tmp/err" ||
    fail "decompose: $(cat "$tmp/err")"
cat "$tmp/out"
[ -s "$tmp/sky.png" ] || fail "no picture"
# One light near (200, 25): within 0.5 degree (a texel is 1.4 degrees).
awk -F'[ =,]+' '/^key/ { n++; if ($2 < 199.5 || $2 > 200.5 || $3 < 24.5 || $3 > 25.5) bad = 1 }
     END { exit !(n == 1 && !bad) }' "$tmp/out" || fail "light not at 200,25"
[ "$(grep -c '^env-sh-[rgb] = ' "$tmp/out")" -eq 3 ] || fail "no env-sh-r/g/b lines"
awk 'length > 190 { exit 1 }' "$tmp/out" || fail "a line longer than a scene file's 190"
grep -q '^key = [^,]*,[^,]*,[^,]*,[^,]*,[^,]*,[^,]*$' "$tmp/out" || fail "key not in colour"
# The printed lines are a scene (colour keys and env-sh-r/g/b parse).
{ echo "height = flat.pfm"; cat "$tmp/out"; } >"$tmp/scene.ini"
"$HFSHADE" render "$tmp/scene.ini" --backend cpu --nphi-env 4 --check 2>"$tmp/err" ||
    fail "printed lines do not render: $(cat "$tmp/err")"
# env-lights auto through the command line.
"$HFSHADE" render --height "$tmp/flat.pfm" --env-map "$tmp/sky.pfm" --env-lights auto \
    --backend cpu --nphi-env 4 --check 2>"$tmp/err" || fail "--env-lights auto: $(cat "$tmp/err")"

# expect_fail NAME NEEDLE ARGS...
expect_fail() {
    local name=$1 needle=$2; shift 2
    rm -f "$tmp/bad.png"
    "$HFSHADE" envmap "$@" >/dev/null 2>"$tmp/err"
    local rc=$?
    if [ $rc -eq 0 ] || [ $rc -ge 128 ]; then fail "[$name] exit status $rc"; return; fi
    [ "$(wc -l <"$tmp/err")" -eq 1 ] || { fail "[$name] not one line: $(cat "$tmp/err")"; return; }
    grep -qF -- "$needle" "$tmp/err" || { fail "[$name] lacks '$needle': $(cat "$tmp/err")"; return; }
    [ ! -e "$tmp/bad.png" ] || { fail "[$name] picture left behind"; return; }
    echo "ok   [$name] $(cat "$tmp/err")"
}
# A 2x1 RGB PFM (little-endian) with a NaN, one with -Inf, one very negative.
printf 'PF\n2 1\n-1.0\n\x00\x00\x80\x3f\x00\x00\xc0\x7f\x00\x00\x80\x3f\x00\x00\x80\x3f\x00\x00\x80\x3f\x00\x00\x80\x3f' >"$tmp/nan.pfm"
printf 'PF\n2 1\n-1.0\n\x00\x00\x80\x3f\x00\x00\x80\x3f\x00\x00\x80\x3f\x00\x00\x80\x3f\x00\x00\x80\xff\x00\x00\x80\x3f' >"$tmp/inf.pfm"
printf 'PF\n2 1\n-1.0\n\x00\x00\x80\x3f\x00\x00\x80\x3f\x00\x00\x80\x3f\x00\x00\x80\x3f\x00\x00\x80\xbf\x00\x00\x80\x3f' >"$tmp/neg.pfm"
expect_fail nan "nan.pfm: pixel (0, 0) is NaN" decompose "$tmp/nan.pfm" --picture "$tmp/bad.png"
expect_fail inf "inf.pfm: pixel (1, 0) is infinite" decompose "$tmp/inf.pfm" --picture "$tmp/bad.png"
expect_fail negative "neg.pfm: texel (1, 0) G is -1" decompose "$tmp/neg.pfm" --picture "$tmp/bad.png"
expect_fail missing "nope.pfm" decompose "$tmp/nope.pfm" --picture "$tmp/bad.png"
expect_fail max-lights "--max-lights" decompose "$tmp/sky.pfm" --max-lights 9
expect_fail min-share "--min-share" decompose "$tmp/sky.pfm" --min-share 2
expect_fail max-radius "--max-radius" decompose "$tmp/sky.pfm" --max-radius -1
# --max-radius: the 0.5-degree sun is taken under 15 degrees, not under 0.1
# (the first candidate wider than the limit ends the search).
"$HFSHADE" envmap decompose "$tmp/sky.pfm" --max-radius 15 >"$tmp/out" 2>"$tmp/err" ||
    fail "max-radius 15: $(cat "$tmp/err")"
grep -q '^key' "$tmp/out" || fail "max-radius 15: no light"
"$HFSHADE" envmap decompose "$tmp/sky.pfm" --max-radius 0.1 >"$tmp/out" 2>"$tmp/err" ||
    fail "max-radius 0.1: $(cat "$tmp/err")"
grep -q '^key' "$tmp/out" && fail "max-radius 0.1: a light wider than 0.1 degree"
# A 1x1 map: no light, a residual.
printf 'PF\n1 1\n-1.0\n\x00\x00\x80\x3f\x00\x00\x80\x3f\x00\x00\x80\x3f' >"$tmp/one.pfm"
"$HFSHADE" envmap decompose "$tmp/one.pfm" >"$tmp/out" 2>"$tmp/err" || fail "1x1: $(cat "$tmp/err")"
grep -q '^key' "$tmp/out" && fail "1x1: a light"
[ $fails -eq 0 ] && echo "envmap_cli: all passed" || echo "envmap_cli: $fails failed"
exit $((fails != 0))
