#!/usr/bin/env bash
# Bad input to the command line tool: every case must exit non-zero with ONE
# line on stderr that names the input, must not crash (no signal exit), and
# must leave no output file.  One good render proves the harness can pass.
# usage: cli_bad_inputs.sh HFSHADE HFGEN BROKEN_DIR
set -u
HFSHADE=$1 HFGEN=$2 BROKEN=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fails=0 cases=0

"$HFGEN" flat --size 16x12 -o "$tmp/flat.pfm" || { echo "FAIL: hfgen"; exit 1; }
sky="3.5449077,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0"

# expect_fail NAME NEEDLE ARGS... : NEEDLE must appear in the message.
expect_fail() {
    local name=$1 needle=$2; shift 2
    cases=$((cases + 1))
    rm -f "$tmp/out.png" "$tmp/out.pfm"
    "$HFSHADE" "$@" >"$tmp/stdout" 2>"$tmp/stderr"
    local rc=$? lines
    lines=$(wc -l <"$tmp/stderr")
    if [ $rc -eq 0 ] || [ $rc -ge 128 ]; then
        echo "FAIL [$name]: exit status $rc"; fails=$((fails + 1)); return
    fi
    if [ "$lines" -ne 1 ]; then
        echo "FAIL [$name]: $lines lines on stderr:"; cat "$tmp/stderr"; fails=$((fails + 1)); return
    fi
    if ! grep -qF -- "$needle" "$tmp/stderr"; then
        echo "FAIL [$name]: message lacks '$needle': $(cat "$tmp/stderr")"; fails=$((fails + 1)); return
    fi
    if ls "$tmp"/out.* >/dev/null 2>&1 || ls "$tmp"/*.tmp-* >/dev/null 2>&1; then
        echo "FAIL [$name]: output file left behind"; fails=$((fails + 1)); return
    fi
    echo "ok   [$name] $(cat "$tmp/stderr")"
}

R="render --backend cpu --nphi-env 4 -o $tmp/out.png --pfm $tmp/out.pfm"
expect_fail missing-height "nope.pfm" $R --height "$tmp/nope.pfm" --env-sh $sky
expect_fail no-height "no height field" $R --env-sh $sky
expect_fail unknown-flag "--bogus" $R --height "$tmp/flat.pfm" --bogus 1
expect_fail bad-k "--k" $R --height "$tmp/flat.pfm" --k 0
expect_fail bad-dx "--dx" $R --height "$tmp/flat.pfm" --dx -2
expect_fail bad-key "--key" $R --height "$tmp/flat.pfm" --key 10,100,2,1
expect_fail bad-env-sh "--env-sh" $R --height "$tmp/flat.pfm" --env-sh 1,2
expect_fail nan-albedo "--albedo" $R --height "$tmp/flat.pfm" --albedo nan
expect_fail missing-env-map "nope.exr" $R --height "$tmp/flat.pfm" --env-map "$tmp/nope.exr"
# Objects (issue 19): counts, ranges, the objects file, the footprint.
expect_fail pin-count "--pin" $R --height "$tmp/flat.pfm" --env-sh $sky --pin 1,2,3
expect_fail pin-width "pin: width 0" $R --height "$tmp/flat.pfm" --env-sh $sky --pin 1,2,3,0
expect_fail box-albedo "albedo 1.5" $R --height "$tmp/flat.pfm" --env-sh $sky --box 1,2,0,1,1,1,1.5,0,0
expect_fail objects-missing "nope.txt" $R --height "$tmp/flat.pfm" --env-sh $sky --objects "$tmp/nope.txt"
printf 'pin = 1,2,3,1\nkey = 1,2,3,4\n' >"$tmp/objs.txt"
expect_fail objects-not-object "objs.txt:2: 'key' is not an object" $R --height "$tmp/flat.pfm" --env-sh $sky --objects "$tmp/objs.txt"
expect_fail geotiff-view "--geotiff: a 3-D view has no georeferencing" $R --height "$tmp/flat.pfm" --env-sh $sky --view ortho --geotiff "$tmp/out.tif"
expect_fail object-off-field "object 1 (pin): (400, 2) is off" $R --height "$tmp/flat.pfm" --env-sh $sky --pin 400,2,3,1 --view ortho
"$HFGEN" flat --size 4x4 -o "$tmp/alb4.pfm" || { echo "FAIL: hfgen"; exit 1; }
"$HFGEN" cones --size 16x12 -o "$tmp/cones.pfm" || { echo "FAIL: hfgen"; exit 1; }
expect_fail albedo-map-size "albedo map is 4x4, the heights are 16x12" $R --height "$tmp/flat.pfm" --env-sh $sky --albedo-map "$tmp/alb4.pfm"
expect_fail albedo-map-range "outside [0, 1]" $R --height "$tmp/flat.pfm" --env-sh $sky --albedo-map "$tmp/cones.pfm"
expect_fail albedo-map-missing "nope.png" $R --height "$tmp/flat.pfm" --env-sh $sky --albedo-map "$tmp/nope.png"
expect_fail specular-range "specular: 2 is out of range" $R --height "$tmp/flat.pfm" --env-sh $sky --specular 2
expect_fail gloss-range "gloss: 0 is out of range" $R --height "$tmp/flat.pfm" --env-sh $sky --gloss 0
expect_fail view-below "elevation -10 is out of range" $R --height "$tmp/flat.pfm" --env-sh $sky --view-dir 0,-10
expect_fail gloss-energy "albedo 0.8 + specular 0.5 is above 1" $R --height "$tmp/flat.pfm" --env-sh $sky --albedo 0.8 --specular 0.5
expect_fail truth-env-word "truth-env" $R --height "$tmp/flat.pfm" --env-sh $sky --truth-env pixels
expect_fail both-envs "both env-sh and env-map" $R --height "$tmp/flat.pfm" --env-sh $sky --env-map "$tmp/x.hdr"
expect_fail missing-value "--dx" $R --height "$tmp/flat.pfm" --dx
expect_fail bad-colormap "--colormap" $R --height "$tmp/flat.pfm" --env-sh $sky --colormap rainbow
printf 'height = flat.pfm\nwhat = 3\n' >"$tmp/bad.ini"
expect_fail ini-unknown-key "bad.ini:2: unknown key 'what'" render "$tmp/bad.ini" -o "$tmp/out.png"
printf 'height = flat.pfm\nk = 99\n' >"$tmp/bad2.ini"
expect_fail ini-range "bad2.ini:2: k: 99 is out of range" render "$tmp/bad2.ini" -o "$tmp/out.png"
expect_fail bad-context "vulkan" info --context vulkan
expect_fail no-output "no output" render --height "$tmp/flat.pfm" --env-sh $sky
expect_fail unwritable-output "/nonexistent-dir/" render --backend cpu --height "$tmp/flat.pfm" --env-sh $sky -o /nonexistent-dir/out.png

# Every broken height file in the corpus, through the whole tool.
for f in "$BROKEN"/height/*; do
    [ -f "$f" ] || continue
    expect_fail "height:$(basename "$f")" "$(basename "$f")" $R --height "$f" --env-sh $sky
done
for f in "$BROKEN"/env/*; do
    [ -f "$f" ] || continue
    expect_fail "env:$(basename "$f")" "$(basename "$f")" $R --height "$tmp/flat.pfm" --env-map "$f"
done

# --check: everything a render does (inputs, outputs planned against them,
# one frame) but writing.  A bad scene or output fails as the render would;
# a good one prints one "ok" line on stdout and leaves nothing behind.
C="render --check --backend cpu --nphi-env 4"
expect_fail check-range "--k" $C --height "$tmp/flat.pfm" --env-sh $sky --k 0
expect_fail check-missing "nope.pfm" $C --height "$tmp/nope.pfm" --env-sh $sky
expect_fail check-clash "flat.pfm" $C --height "$tmp/flat.pfm" --env-sh $sky --pfm "$tmp/flat.pfm"
expect_fail check-twice "--check" $C --check --height "$tmp/flat.pfm" --env-sh $sky
# The 3-D view's flags (issue 16).
V="$R --height $tmp/flat.pfm --env-sh $sky"
expect_fail view-mode "--view: 'side'" $V --view side
expect_fail camera-short "--camera: '10,20'" $V --view ortho --camera 10,20
expect_fail camera-nan "--camera: 'a,20,5,30'" $V --view ortho --camera a,20,5,30
expect_fail camera-elev "--camera: elevation 95" $V --view perspective --camera 0,95,5,30
expect_fail camera-dist "--camera: distance -5" $V --view perspective --camera 0,45,-5,30
expect_fail camera-fov "--camera: field of view 180" $V --view perspective --camera 0,45,5,180
expect_fail view-size "--view-size: '0x10'" $V --view ortho --view-size 0x10
expect_fail view-size-form "--view-size: '64'" $V --view ortho --view-size 64
expect_fail exaggeration "--exaggeration: '0'" $V --view ortho --exaggeration 0
expect_fail camera-no-view "--camera: needs --view" $V --camera 0,45,5,30
# Point queries (issue 19): the points file and the points themselves.
Q="query --backend cpu --height $tmp/flat.pfm --key 30,20,1,10"
printf '1 2 3\n4 5\n' >"$tmp/pts2.txt"
printf '# none\n\n' >"$tmp/pts0.txt"
printf '1 2 3 4\n' >"$tmp/pts4.txt"
printf '1 2 3\n100 2 3\n' >"$tmp/ptsoff.txt"
expect_fail query-no-points "give --points" $Q
expect_fail query-missing "nope.txt" $Q --points "$tmp/nope.txt"
expect_fail query-short "pts2.txt:2: expected three finite numbers" $Q --points "$tmp/pts2.txt"
expect_fail query-empty "pts0.txt: no points" $Q --points "$tmp/pts0.txt"
expect_fail query-extra "pts4.txt:1: unexpected text" $Q --points "$tmp/pts4.txt"
expect_fail query-off "point 2 (100, 2) is not over the field" $Q --points "$tmp/ptsoff.txt"
expect_fail query-no-key "no key light" query --backend cpu --height "$tmp/flat.pfm" --points "$tmp/ptsoff.txt"
printf '# a pin\n3 4 0.5\n' >"$tmp/pts1.txt"
"$HFSHADE" $Q --points "$tmp/pts1.txt" >"$tmp/q.out" 2>"$tmp/q.err" &&
    [ "$(tail -1 "$tmp/q.out")" = "3 4 0.5 1.000000" ] ||
    { echo "FAIL [query-good]: $(cat "$tmp/q.out" "$tmp/q.err")"; fails=$((fails + 1)); }
cases=$((cases + 1))
"$HFGEN" cones --size 2100x3 -o "$tmp/wide.pfm" >/dev/null || { echo "FAIL: hfgen"; exit 1; }
if "$HFSHADE" info >/dev/null 2>&1; then # a GLES refusal needs a context to refuse
    HFS_GL_STRICT_LIMITS=1 expect_fail check-refused "GL_MAX_TEXTURE_SIZE" render --check \
        --backend gles --height "$tmp/wide.pfm" --env-sh $sky
fi
cases=$((cases + 1))
before=$(ls "$tmp" | sort)
out=$("$HFSHADE" $C --height "$tmp/flat.pfm" --env-sh $sky -o "$tmp/out.png" 2>"$tmp/stderr")
if [ $? -eq 0 ] && [ "$(printf '%s\n' "$out" | wc -l)" -eq 1 ] && [[ $out == *": ok ("* ]] &&
   [ ! -s "$tmp/stderr" ] && [ "$(ls "$tmp" | sort)" = "$before" ]; then
    echo "ok   [check-good] $out"
else
    echo "FAIL [check-good]: '$out' $(cat "$tmp/stderr")"; fails=$((fails + 1))
fi

# The good case: both outputs written, nothing else.
cases=$((cases + 1))
if "$HFSHADE" $R --height "$tmp/flat.pfm" --env-sh $sky --colormap terrain --quiet && [ -s "$tmp/out.png" ] && [ -s "$tmp/out.pfm" ]; then
    echo "ok   [good-render]"
else
    echo "FAIL [good-render]"; fails=$((fails + 1))
fi
echo "$((cases - fails)) passed, $fails failed"
[ $fails -eq 0 ]
