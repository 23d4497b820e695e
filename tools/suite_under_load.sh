#!/usr/bin/env bash
# suite_under_load.sh — the whole test suite, RUNS times in a row, while
# HOGS CPU-bound processes run beside it (issue 34: tests wait on the event
# they test, not on wall time a busy machine cannot meet).  Each hog is a
# busy shell loop at normal priority; they are killed when the script ends,
# however it ends.  Prints one line per run and exits 1 if any run failed.
#
#   tools/suite_under_load.sh BUILD [RUNS=3] [HOGS=3] [-- CTEST ARGS...]
#
# e.g. HFS_REQUIRE_GL=1 tools/suite_under_load.sh build 3 3
set -u
BUILD=${1:?usage: suite_under_load.sh BUILD [RUNS] [HOGS] [-- CTEST ARGS]}
RUNS=${2:-3}
HOGS=${3:-3}
shift $(( $# < 3 ? $# : 3 ))
[ "${1:-}" = -- ] && shift
hogs=()
stop_hogs() { [ ${#hogs[@]} -gt 0 ] && kill "${hogs[@]}" 2>/dev/null; wait 2>/dev/null; }
trap stop_hogs EXIT
for _ in $(seq "$HOGS"); do
    bash -c 'while :; do :; done' &
    hogs+=($!)
done
echo "suite_under_load: $HOGS CPU hogs (pids ${hogs[*]}) on $(nproc) cores"
failed=0
for run in $(seq "$RUNS"); do
    log="$BUILD/suite_under_load.$run.log"
    start=$(date +%s)
    ctest --test-dir "$BUILD" -j2 --output-on-failure "$@" >"$log" 2>&1
    rc=$?
    summary=$(grep -E 'tests passed' "$log" | tail -1)
    echo "run $run: exit $rc, $summary, $(( $(date +%s) - start )) s, load $(cut -d' ' -f1-3 /proc/loadavg) ($log)"
    if [ $rc -ne 0 ]; then
        failed=1
        sed -n '/The following tests FAILED/,$p' "$log"
    fi
done
exit $failed
