#!/usr/bin/env bash
# mutate.sh — does the test suite notice when the product breaks?
#
#   tools/mutate.sh [-l LIST] [-o REPORT.md] [-k ID[,ID...]] [-j JOBS] [-w WORKDIR]
#                   [-t HINTS]
#
# Applies each mutation of LIST (default tools/mutations.txt) alone to a
# scratch copy of the working tree (tracked and untracked, not ignored
# files: WORKDIR/src, default build-mutate/), rebuilds it (WORKDIR/build,
# RelWithDebInfo) and runs the ctest suite, stopping at the first failing
# test.  A mutant is KILLED when a test fails, SURVIVED when the whole suite
# passes, and NO-BUILD when it does not compile (not counted: the compiler,
# not the suite, caught it).  The unmutated copy is built and tested first
# and must pass (HFS_REQUIRE_GL=1, so no GL test can hide behind a skip).
#
# LIST format: one mutation per line, fields separated by TABs,
#   ID  FILE  FIND  REPLACE  WHAT
# FIND must occur exactly once in FILE (a mutation that no longer applies
# is reported as STALE: fix the list).  Text in FIND/REPLACE is literal;
# "\t" and "\n" stand for a tab and a newline.  Lines starting with # are
# comments.
#
# HINTS (optional): lines "ID TEST", the test that killed mutant ID before
# (docs/MUTATION.md's tables; tools/mutate_hints.sh writes them from the
# reports).  That test runs first, alone; when it fails the mutant is
# KILLED by it, otherwise the whole suite runs as above.  Only the order
# changes (a test of the suite fails or none does), and a run takes
# seconds a mutant instead of the unit/io group's minute or more.
#
# The report (REPORT, default WORKDIR/mutate-report.md) is a markdown table:
# id, what, verdict, the first test that failed, seconds.  Exit 0 when the
# killed share of the mutants that built is at least 95% (MUTATE_MIN_KILLED,
# percent), else 1.  Run nightly (about 1-2 min a mutant on 2 cores, more
# for a survivor, which runs the whole suite): not part of .ci/run.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
list="$root/tools/mutations.txt"
work="$root/build-mutate"
report=""
only=""
jobs=2
hints=""
while getopts "l:o:k:j:w:t:h" opt; do
    case $opt in
    l) list="$(realpath "$OPTARG")" ;;
    o) report="$(realpath -m "$OPTARG")" ;;
    k) only=",$OPTARG," ;;
    j) jobs="$OPTARG" ;;
    w) work="$(realpath -m "$OPTARG")" ;;
    t) hints="$(realpath "$OPTARG")" ;;
    *) sed -n '2,35p' "$0" | sed 's/^# \{0,1\}//'; exit 2 ;;
    esac
done
[ -n "$report" ] || report="$work/mutate-report.md"
[ -r "$list" ] || { echo "mutate.sh: $list: cannot read the mutation list" >&2; exit 2; }
min_killed="${MUTATE_MIN_KILLED:-95}"
export HFS_REQUIRE_GL=1

src="$work/src"
bld="$work/build"
log="$work/log"
mkdir -p "$work" "$log"
echo "mutate.sh: copying the working tree to $src"
rm -rf "$src"
mkdir -p "$src"
(cd "$root" && git ls-files -co --exclude-standard -z | tar --null -T - -cf -) | (cd "$src" && tar -xf -)
# tar keeps the files' times: a build left by a run stopped mid-mutant
# would be newer than the restored source and keep the mutant.
find "$src" -type f -exec touch {} +

build_and_test() { # $1 = log name, $2 = a test to run first; prints "verdict first_failed"
    local name="$1" hint="${2:-}"
    if ! cmake --build "$bld" -j"$jobs" >"$log/$name.build" 2>&1; then
        echo "NO-BUILD -"
        return
    fi
    local out="$log/$name.ctest"
    : >"$out"
    # The hinted test alone first (-t HINTS): a failure there is a kill.
    if [ -n "$hint" ] &&
       ! ctest --test-dir "$bld" -R "^${hint}\$" --timeout 900 >>"$out" 2>&1 &&
       grep -q -E '\*\*\*(Failed|Timeout|Exception)' "$out"; then
        echo "KILLED $hint"
        return
    fi
    # Unit and io tests first (seconds), then the rest; stop at the first
    # failure.  Tests that hang count as failures through their TIMEOUTs.
    for sel in "-L unit|io" "-LE unit|io"; do
        # shellcheck disable=SC2086
        if ! ctest --test-dir "$bld" $sel -j"$jobs" --stop-on-failure --timeout 900 \
                >>"$out" 2>&1; then
            local first
            first="$(grep -m1 -E '\*\*\*(Failed|Timeout|Exception)' "$out" |
                     sed -E 's/.*Test +#[0-9]+: ([^ ]+).*/\1/')"
            echo "KILLED ${first:-?}"
            return
        fi
    done
    echo "SURVIVED -"
}

echo "mutate.sh: configuring $bld"
cmake -S "$src" -B "$bld" -DCMAKE_BUILD_TYPE=RelWithDebInfo >"$log/configure" 2>&1 ||
    { echo "mutate.sh: configure failed (see $log/configure)" >&2; exit 2; }
echo "mutate.sh: the unmutated tree must pass"
read -r verdict first < <(build_and_test baseline)
if [ "$verdict" != SURVIVED ]; then
    echo "mutate.sh: the unmutated tree does not pass ($verdict $first; $log/baseline.*)" >&2
    exit 2
fi

apply() { # file find replace -> 0 applied, 3 stale
    FIND="$2" REPLACE="$3" perl -0777 -i -e '
        my $f = $ENV{FIND}; my $r = $ENV{REPLACE};
        for ($f, $r) { s/\\t/\t/g; s/\\n/\n/g; }
        local $/; my $s = <>;
        my $n = () = $s =~ /\Q$f\E/g;
        if ($n != 1) { print $s; exit 3; }
        $s =~ s/\Q$f\E/$r/;
        print $s;' "$1"
}

{
    echo "| id | mutation | verdict | first failing test | s |"
    echo "|---|---|---|---|---|"
} >"$report"
killed=0 survived=0 nobuild=0 stale=0
while IFS=$'\t' read -r id file find replace what; do
    case "$id" in ''|'#'*) continue ;; esac
    [ -z "$only" ] || [[ "$only" == *",$id,"* ]] || continue
    t0=$(date +%s)
    cp "$src/$file" "$work/orig"
    hint=""
    [ -z "$hints" ] || hint="$(awk -v id="$id" '$1 == id { print $2; exit }' "$hints")"
    if apply "$src/$file" "$find" "$replace"; then
        read -r verdict first < <(build_and_test "$id" "$hint")
    else
        verdict=STALE first=-
    fi
    cp "$work/orig" "$src/$file"
    touch "$src/$file"
    secs=$(( $(date +%s) - t0 ))
    case $verdict in
    KILLED) killed=$((killed + 1)) ;;
    SURVIVED) survived=$((survived + 1)) ;;
    NO-BUILD) nobuild=$((nobuild + 1)) ;;
    STALE) stale=$((stale + 1)) ;;
    esac
    printf '%-4s %-9s %-40s %4ss  %s\n' "$id" "$verdict" "$first" "$secs" "$what"
    echo "| $id | $what | $verdict | $first | $secs |" >>"$report"
done <"$list"
cmake --build "$bld" -j"$jobs" >/dev/null 2>&1 || true # leave the copy built unmutated

counted=$((killed + survived))
pct=0
[ "$counted" -eq 0 ] || pct=$((100 * killed / counted))
summary="mutate.sh: $killed killed, $survived survived, $nobuild did not build, $stale stale; killed $pct% of $counted"
{
    echo
    echo "$summary"
} >>"$report"
echo "$summary (report: $report)"
[ "$stale" -eq 0 ] && [ "$counted" -gt 0 ] && [ "$pct" -ge "$min_killed" ]
