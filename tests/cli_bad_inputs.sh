#!/usr/bin/env bash
# Bad input to the command line tool: every case must exit non-zero with ONE
# line on stderr that names the input, must not crash (no signal exit), and
# must leave no output file.  One good render proves the harness can pass.
# The last section (issue 34) runs every program the project builds on a
# bad command line: TOOL=PATH arguments name the others.
# usage: cli_bad_inputs.sh HFSHADE HFGEN BROKEN_DIR [TOOL=PATH ...]
set -u
HFSHADE=$1 HFGEN=$2 BROKEN=$3
declare -A TOOL=([hfshade]=$HFSHADE [hfgen]=$HFGEN)
for kv in "${@:4}"; do TOOL[${kv%%=*}]=${kv#*=}; done
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
# The view's background and haze (issue 41).
expect_fail background "--background: 'sea'" $V --view ortho --background sea
expect_fail background-hex "--background: '#12345g'" $V --view ortho --background '#12345g'
expect_fail background-rgb "--background: '1,-2,3'" $V --view ortho --background 1,-2,3
expect_fail background-short "--background: '1,2'" $V --view ortho --background 1,2
expect_fail haze "--haze: '51'" $V --view ortho --haze 51
expect_fail haze-word "--haze: 'thick'" $V --view ortho --haze thick
expect_fail haze-nan "--haze: 'nan'" $V --view ortho --haze nan
expect_fail background-no-view "--background: needs --view" $V --background studio
expect_fail haze-no-view "--haze: needs --view" $V --haze auto
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
    # issue 39: a field over the ES 3.0 minimum renders in tiles unless its
    # lights see terrain at any distance (a local light): then one line
    # naming the way out; the 3-D view is not tiled
    HFS_GL_STRICT_LIMITS=1 expect_fail check-refused "GL_MAX_TEXTURE_SIZE" render --check \
        --backend gles --height "$tmp/wide.pfm" --env-sh $sky --view ortho
    HFS_GL_STRICT_LIMITS=1 expect_fail over-limit-way-out "the cpu backend renders any size" \
        render --backend gles --height "$tmp/wide.pfm" --env-sh $sky --local 10,1,5,0.5,100 \
        -o "$tmp/out.png"
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

# ---- every program's bad command line (issue 34) ---------------------------
# An unknown flag, a missing value, a bad value, an unknown subcommand, case
# or backend, a missing argument: non-zero exit (no signal, no hang),
# nothing on stdout, at most two lines on stderr, the first naming the
# problem (NEEDLE), a second one only pointing at --help.
# expect_usage TOOL NAME NEEDLE ARGS...
expect_usage() {
    local tool=$1 name=$2 needle=$3; shift 3
    local bin=${TOOL[$tool]:-} rc lines why=""
    if [ -z "$bin" ]; then echo "skip [$tool/$name]: no $tool given"; return; fi
    cases=$((cases + 1))
    timeout -k 2 30 "$bin" "$@" >"$tmp/stdout" 2>"$tmp/stderr" </dev/null
    rc=$?
    lines=$(wc -l <"$tmp/stderr")
    if [ $rc -eq 0 ] || [ $rc -ge 124 ]; then why="exit status $rc"
    elif [ -s "$tmp/stdout" ]; then why="$(wc -l <"$tmp/stdout") lines on stdout"
    elif [ "$lines" -lt 1 ] || [ "$lines" -gt 2 ]; then why="$lines lines on stderr"
    elif ! head -1 "$tmp/stderr" | grep -qF -- "$needle"; then why="first line lacks '$needle'"
    elif [ "$lines" -eq 2 ] && ! sed -n 2p "$tmp/stderr" | grep -qF -- "--help"; then
        why="second line is not a pointer to --help"
    fi
    if [ -n "$why" ]; then
        echo "FAIL [$tool/$name]: $why"; head -4 "$tmp/stderr" | sed 's/^/     stderr: /'
        fails=$((fails + 1))
    else
        echo "ok   [$tool/$name] $(head -1 "$tmp/stderr")"
    fi
}
# expect_help TOOL ARGS...: the usage on stdout, nothing on stderr, exit 0.
expect_help() {
    local tool=$1; shift
    local bin=${TOOL[$tool]:-}
    [ -n "$bin" ] || return 0
    cases=$((cases + 1))
    if timeout -k 2 30 "$bin" "$@" >"$tmp/stdout" 2>"$tmp/stderr" </dev/null &&
       [ -s "$tmp/stdout" ] && [ ! -s "$tmp/stderr" ]; then
        echo "ok   [$tool/help $*] $(wc -l <"$tmp/stdout") lines"
    else
        echo "FAIL [$tool/help $*]: no usage on stdout, or stderr, or a failing exit"
        fails=$((fails + 1))
    fi
}
U=expect_usage
$U hfshade no-command "no command"
$U hfshade unknown-command "frob" frob
$U hfshade flag-no-value "--bogus: unknown flag" render --bogus
$U hfshade info-no-value "--context: missing value" info --context
$U hfshade envmap-none "envmap" envmap
$U hfshade envmap-unknown "frob" envmap frob
$U hfshade envmap-no-map "no MAP" envmap decompose
$U hfshade envmap-no-value "--max-lights: missing value" envmap decompose "$tmp/x.pfm" --max-lights
# The GIS commands (issue 39; parsed before GDAL is needed, so in every build).
$U hfshade svf-no-dem "no DEM" svf -o "$tmp/x.tif"
$U hfshade svf-bad-directions "--directions: '0'" svf "$tmp/x.tif" -o "$tmp/y.tif" --directions 0
$U hfshade horizon-no-azimuths "no azimuths" horizon "$tmp/x.tif" -o "$tmp/h"
$U hfshade horizon-bad-convention "'north'" horizon "$tmp/x.tif" -o "$tmp/h" --step 45 --convention north
$U hfshade openness-svf-flag "--lambertian: unknown option" openness "$tmp/x.tif" -o "$tmp/y.tif" --lambertian
$U hfshade svf-bad-tile "--tile: '-64'" svf "$tmp/x.tif" -o "$tmp/y.tif" --radius 300 --tile -64
$U hfshade sun-no-datetime "no --datetime given" sun "$tmp/x.tif" -o "$tmp/y.tif"
$U hfshade sun-bad-datetime "month 13" sun "$tmp/x.tif" -o "$tmp/y.tif" --datetime 2026-13-01T10:00Z
$U hfshade sun-no-timezone "has no time zone" sun "$tmp/x.tif" -o "$tmp/y.tif" --datetime 2026-06-21T10:00
$U hfshade sun-bad-linke "--linke: '0.5'" sun "$tmp/x.tif" -o "$tmp/y.tif" --datetime 2026-06-21T10:00Z --linke 0.5
$U hfshade insolation-backwards "--to: 2026-06-20T00:00Z is not after" insolation "$tmp/x.tif" -o "$tmp/y.tif" --from 2026-06-21T00:00Z --to 2026-06-20T00:00Z
$U hfshade insolation-bad-step "--step: '0'" insolation "$tmp/x.tif" -o "$tmp/y.tif" --from 2026-06-21T00:00Z --to 2026-06-22T00:00Z --step 0
$U hfshade insolation-many-steps "at most 100000" insolation "$tmp/x.tif" -o "$tmp/y.tif" --from 2026-01-01T00:00Z --to 2027-01-01T00:00Z --step 1
$U hfgen no-kind "no kind"
$U hfgen unknown-kind "'volcano'" volcano --size 8x8 -o "$tmp/out.pfm"
$U hfgen unknown-kind-bare "'volcano'" volcano
$U hfgen unknown-flag "--bogus" flat --bogus 1
$U hfgen missing-value "--size: missing value" flat --size
$U hfgen bad-size "--size: '0x3'" flat --size 0x3 -o "$tmp/out.pfm"
$U hfgen bad-seed "--seed: 'x'" flat --size 4x4 --seed x -o "$tmp/out.pfm"
$U hfgen no-output "no output" flat --size 4x4
$U hfgen stray "stray" flat --size 4x4 stray -o "$tmp/out.pfm"
$U hfgen crop-no-input "no input" crop -o "$tmp/out.pfm"
$U hfgen crop-no-rect "--rect" crop "$tmp/flat.pfm" -o "$tmp/out.pfm"
$U hfgen sky-bad-sun "--sun: '1'" sky --sun 1 -o "$tmp/out.pfm"
$U hfgen sky-unknown "--bogus" sky --bogus 1 -o "$tmp/out.pfm"
$U hfgen sky-no-value "--noise: missing value" sky -o "$tmp/out.pfm" --noise
$U hfgen sky-no-output "no output" sky
$U hfstress unknown-case "'nosuchcase'" --case nosuchcase
$U hfstress unknown-backend "'vulkan'" --backend vulkan
$U hfstress unknown-flag "--bogus" --bogus
$U hfstress missing-value "--case: missing value" --case
$U hfstress stray "stray" stray
$U hfstress bad-lights "'foo'" --list --lights foo
$U hfstress bad-subsample "--subsample: '3'" --list --subsample 3
$U hfstress bad-visibility "--visibility: 'x'" --list --visibility x
$U hfbench no-output "no output"
$U hfbench unknown-flag "--bogus: unknown" --bogus
$U hfbench missing-value "-o: missing value" -o
$U hfbench stray "stray" stray
$U hfbench bad-size "--size: '1'" -o "$tmp/b.csv" --size 1
$U hfbench bad-lights "'moon'" -o "$tmp/b.csv" --lights moon --size 8 --scenes flat
$U hfbench bad-truth-env "--truth-env: 'x'" -o "$tmp/b.csv" --truth-env x
$U bench_env no-mode "no mode"
$U bench_env unknown-mode "'frob'" frob
$U bench_env time-short "time: needs W H" time
$U bench_env time-bad "'x'" time 4 x
$U bench_env track-bad "'x'" track x
$U bench_env file-short "file: needs MAP" file
$U bench_env gloss-short "gloss: needs MAP S" gloss x.exr
$U bench_env extra "9" time 4 4 1 1 9
$U gles_bench unknown-flag "--bogus" --bogus
$U gles_bench stray "stray" stray
$U gles_bench missing-value "--size: missing value" --size
$U gles_bench bad-size "--size: 'x'" --size x
$U gles_bench bad-precision "'fp64'" --size 16 --frames 1 --precision fp64
$U gles_bench bad-path "'foo'" --size 16 --frames 1 --path foo
$U gles_bench bad-lights "'sun'" --size 16 --frames 1 --lights sun
$U gles_bench bad-dx "--dx: '-1'" --size 16 --frames 1 --dx -1
$U hfshade-kiosk no-scene "no scene file"
$U hfshade-kiosk unknown-flag "--bogus" "$tmp/x.ini" --bogus
$U hfshade-kiosk missing-value "--input: missing value" "$tmp/x.ini" --input
$U hfs-capture-info no-device "no device"
$U hfs-capture-info unknown-flag "--bogus" --bogus
$U hfs-capture-info missing-device "video9" "$tmp/video9"
$U hfs-capture-synth no-dir "no directory"
$U hfs-capture-synth unknown-flag "--bogus" "$tmp/syn" --bogus
$U hfs-capture-synth missing-value "--frames: missing value" "$tmp/syn" --frames
$U hfs-capture-synth bad-frames "--frames: 'x'" "$tmp/syn" --frames x
$U hfs-capture-synth bad-sky "'moon'" "$tmp/syn" --sky moon
$U hfs-capture-synth two-dirs "syn2" "$tmp/syn" "$tmp/syn2"
for t in hfshade hfgen hfstress hfbench bench_env gles_bench hfshade-kiosk hfs-capture-info \
         hfs-capture-synth; do
    expect_help "$t" --help
done
expect_help hfshade envmap --help
for c in svf horizon openness sun insolation; do
    expect_help hfshade "$c" --help
done

echo "$((cases - fails)) passed, $fails failed"
[ $fails -eq 0 ]
