#!/usr/bin/env bash
# ci_skips.sh — what a ctest run skipped, and why; fails on a skip nobody
# expected.
#
#   tools/ci_skips.sh BUILD_DIR CTEST_OUTPUT [EXPECTED]
#
# CTEST_OUTPUT is ctest's standard output of the run (.ci/run tees it); the
# reasons come from the run's log (BUILD_DIR/Testing/Temporary/LastTest.log):
# the first line of the test's output that starts with "SKIP".  EXPECTED
# (default .ci/expected-skips) lists the skips this machine kind is known to
# have, one per line: the test's name, a TAB, and a piece of text its reason
# must contain.  Prints the count and one line per skipped test; exits 1
# when a test skipped that is not listed, or for another reason than the
# listed one.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:?usage: ci_skips.sh BUILD_DIR CTEST_OUTPUT [EXPECTED]}"
out="${2:?usage: ci_skips.sh BUILD_DIR CTEST_OUTPUT [EXPECTED]}"
expected="${3:-$root/.ci/expected-skips}"
log="$build/Testing/Temporary/LastTest.log"
[ -r "$out" ] || { echo "ci_skips.sh: $out: cannot read the ctest output" >&2; exit 2; }
[ -r "$log" ] || { echo "ci_skips.sh: $log: cannot read the test log" >&2; exit 2; }

mapfile -t skipped < <(sed -nE 's/.*Test +#[0-9]+: ([^ ]+) .*\*\*\*Skipped.*/\1/p' "$out" | sort)
echo "skipped: ${#skipped[@]} test(s)"
bad=0
for t in "${skipped[@]}"; do
    # The test's block in the log: from "Test: NAME" to its end marker.
    reason="$(awk -v t="$t" '
        $0 ~ "^[0-9]+/[0-9]+ Test: " && $NF == t { on = 1; next }
        on && /^<end of output>/ { exit }
        on && /^SKIP/ { print; exit }' "$log")"
    [ -n "$reason" ] || reason="(no SKIP line in its output)"
    want="$(awk -F'\t' -v t="$t" '$1 == t { print $2; exit }' "$expected" 2>/dev/null || true)"
    if [ -n "$want" ] && [[ "$reason" == *"$want"* ]]; then
        echo "  $t: $reason"
    else
        echo "  $t: $reason  <-- UNEXPECTED skip (${expected#"$root"/} ${want:+wants \"$want\"}${want:-has no entry})"
        bad=1
    fi
done
exit $bad
