# bench_lib.sh — sourced by the benchmark scripts that share the ground-truth
# shellcheck shell=bash
# cache (tools/bench_reference.sh, tools/bench_slice.sh).

# The wall time hfshade printed in LOG ("..., 1.23 s"), or "-" without one.
bench_seconds() {
    if [ -f "$1" ]; then sed -n 's/.*, \([0-9.]*\) s$/\1/p' "$1" | tail -n 1; else echo -; fi
}

# bench_truth HFS TRUTH.pfm SCENE-ARGS...: renders the ground truth (1024
# samples per light) into TRUTH.pfm unless it is already there, its log
# (with the wall time) beside it as TRUTH.log.
bench_truth() {
    local hfs=$1 truth=$2
    shift 2
    [ -s "$truth" ] ||
        "$hfs" render "$@" --backend truth --truth-samples 1024 --pfm "$truth" 2>"${truth%.pfm}.log"
}
