# bench_lib.sh — sourced by the benchmark scripts that share the ground-truth
# shellcheck shell=bash
# cache (tools/bench_reference.sh, tools/bench_slice.sh).

# The wall time hfshade printed in LOG ("..., 1.23 s"), or "-" without one.
bench_seconds() {
    if [ -f "$1" ]; then sed -n 's/.*, \([0-9.]*\) s$/\1/p' "$1" | tail -n 1; else echo -; fi
}

# bench_truth HFS TRUTH.pfm SCENE-ARGS...: renders the ground truth (1024
# samples per light) into TRUTH.pfm unless it is already there for the same
# arguments and truth version (TRUTH.key beside it; version 2: the truth
# integrates an --env-map itself, not its SH; 3: exact horizons), its log
# (with the wall time) beside it as TRUTH.log.
bench_truth() {
    local hfs=$1 truth=$2
    shift 2
    local key="truth-v3 $*"
    if [ -s "$truth" ] && [ "$(cat "${truth%.pfm}.key" 2>/dev/null)" = "$key" ]; then
        return 0
    fi
    "$hfs" render "$@" --backend truth --truth-samples 1024 --pfm "$truth" 2>"${truth%.pfm}.log"
    printf '%s\n' "$key" >"${truth%.pfm}.key"
}

# bench_scenes GEN CACHE N: the benchmark scenes at N x N (cones, the
# fractal at relief 0.25, the DEM window at (140, 100) where it fits, as
# tools/bench_scene.c takes it), made into CACHE; sets the array `scenes`
# of "name|height file|scene flags".
bench_scenes() {
    local gen=$1 c=$2 n=$3 x0=140 y0=100
    "$gen" cones --size "${n}x${n}" -o "$c/cones$n.pfm"
    "$gen" fractal --size "${n}x${n}" --relief 0.25 -o "$c/fractal$n.pfm"
    [ $((x0 + n)) -le 403 ] || x0=0
    [ $((y0 + n)) -le 344 ] || y0=0
    "$gen" crop data/jacksboro.png --rect "$x0,$y0,$n,$n" -o "$c/dem$n.pfm"
    # shellcheck disable=SC2034 # the caller reads it
    scenes=("cones|$c/cones$n.pfm|--dx 1"
            "fractal|$c/fractal$n.pfm|--dx 1"
            "dem|$c/dem$n.pfm|--dx 83 --zscale 2")
}

# bench_rough_scenes GEN CACHE N: bench_scenes and the rough ones after
# them: the fractal at relief 1 at N x N ("rough") and hfgen's Hurst-0.25
# and Hurst-0.8 fields at 64x64 (issue 36 item 4's).
bench_rough_scenes() {
    local gen=$1 c=$2 n=$3
    bench_scenes "$gen" "$c" "$n"
    "$gen" fractal --size "${n}x${n}" --relief 1 -o "$c/rough$n.pfm"
    "$gen" fractal --size 64x64 --hurst 0.25 -o "$c/hurst025.pfm"
    "$gen" fractal --size 64x64 --hurst 0.8 -o "$c/hurst08.pfm"
    scenes+=("rough|$c/rough$n.pfm|--dx 1" "hurst 0.25 (64²)|$c/hurst025.pfm|--dx 1"
             "hurst 0.8 (64²)|$c/hurst08.pfm|--dx 1")
}

# bench_scene_keys ENTRY: one entry of `scenes` as the bench programs take
# it: sets `name`, `hf` (the height file) and the array `keys` (its scene
# flags as KEY=VALUE words).
bench_scene_keys() {
    local extra flags i
    # shellcheck disable=SC2034 # the caller reads name and hf
    IFS='|' read -r name hf extra <<<"$1"
    keys=()
    read -r -a flags <<<"$extra"
    for ((i = 0; i < ${#flags[@]}; i += 2)); do keys+=("${flags[i]#--}=${flags[i + 1]}"); done
}

# bench_builds LABEL=DIR...: the builds a side-by-side script compares
# (default now=build): sets BUILDS (the arguments), and from the first
# build GEN, HFS0 (its hfgen and hfshade) and C (its bench-cache, made).
bench_builds() {
    [ $# -gt 0 ] || set -- now=build
    BUILDS=("$@")
    local b0=${BUILDS[0]#*=}
    # shellcheck disable=SC2034 # the caller reads them
    GEN=$b0/tools/hfgen HFS0=$b0/tools/hfshade
    C=$b0/bench-cache
    mkdir -p "$C"
}

# bench_frame_ms HFS ARGS...: the median frame time (ms) `render --time 3`
# prints for the scene ARGS (the image goes to $C/frame-time.png).
bench_frame_ms() {
    local hfs=$1
    shift
    "$hfs" render "$@" --time 3 --quiet -o "$C/frame-time.png" 2>&1 |
        awk '$1 == "frame" { print $2 }'
}

# bench_median: the median of the numbers on standard input, one a line.
bench_median() {
    sort -g | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'
}

# bench_frame_stats BUILD FRAMES DIR ARGS...: "median_frame_ms texture_MiB"
# of BUILD's `hfshade render ARGS --time FRAMES` (every pass run), the
# image to DIR.
bench_frame_stats() {
    local b=$1 f=$2 dir=$3
    shift 3
    "$b/tools/hfshade" render "$@" --time "$f" --pfm "$dir/ab.pfm" |
        awk '$1 == "frame" {f = $2} /^texture memory/ {m = $3} END {print f, m}'
}

# bench_ab A B ROUNDS FRAMES DIR "FLAGS_A" "FLAGS_B" ARGS...: the frames of
# ARGS on builds A and B (each with its extra flags), alternating within
# each of ROUNDS rounds so that drift on a shared machine hits both:
# "a_ms b_ms ratio a_MiB b_MiB", medians of the builds' frame times and of
# the per-round ratios B / A, and the last round's texture memory.
bench_ab() {
    local a=$1 b=$2 r=$3 f=$4 dir=$5 fa=$6 fb=$7 i ta tb ma mb
    shift 7
    : >"$dir/ab-a" && : >"$dir/ab-b" && : >"$dir/ab-r"
    for ((i = 0; i < r; ++i)); do
        # shellcheck disable=SC2086 # the flags are words
        read -r ta ma <<<"$(bench_frame_stats "$a" "$f" "$dir" "$@" $fa)"
        # shellcheck disable=SC2086
        read -r tb mb <<<"$(bench_frame_stats "$b" "$f" "$dir" "$@" $fb)"
        echo "$ta" >>"$dir/ab-a"
        echo "$tb" >>"$dir/ab-b"
        awk -v a="$ta" -v b="$tb" 'BEGIN {print b / a}' >>"$dir/ab-r"
    done
    echo "$(bench_median <"$dir/ab-a") $(bench_median <"$dir/ab-b") $(bench_median <"$dir/ab-r")" \
        "$ma $mb"
}
