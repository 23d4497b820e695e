#!/usr/bin/env bash
# tools/fuzz.sh [SECONDS_PER_TARGET] — bounded libFuzzer run of every fuzz
# target (tests/fuzz/, tests/fuzz.cmake): configures build-fuzz/ with clang and
# -DHFS_FUZZ=ON (RelWithDebInfo, ASan + UBSan, stb compiled in so it is
# instrumented too), builds target hfs_fuzz, and runs each target for
# SECONDS_PER_TARGET (default 60) on a scratch copy of its seed corpus, so the
# checked-in corpus (tests/fuzz/corpus/<target>) is never modified.  Targets
# run side by side, one per core (HFS_FUZZ_JOBS overrides).
#
# Prints one line per target (executions, coverage, corpus growth) and exits 1
# if any target found a crash, leak, timeout, out-of-memory or sanitizer
# report, naming the reproducer (build-fuzz/fuzz-artifacts/<target>/...) and
# its log.  A reproducer becomes a regression test by copying it to
# tests/fuzz/regressions/<target>/ (then fix the code; ctest replays it).
#
#   CI (.ci/run):   tools/fuzz.sh 20       (about 2 minutes on 2 cores, build included)
#   nightly:        tools/fuzz.sh 600
#   keep what a long run found as seeds (minimised, then review and commit):
#     build-fuzz/tests/fuzz_T -merge=1 tests/fuzz/corpus/T build-fuzz/fuzz-scratch/T
set -euo pipefail
cd "$(dirname "$0")/.."

secs=${1:-60}
case $secs in '' | *[!0-9]*) echo "usage: $0 [SECONDS_PER_TARGET]" >&2; exit 2 ;; esac
build=build-fuzz
jobs=${HFS_FUZZ_JOBS:-$(nproc)}

# Target, -max_len (bytes: small files find bugs faster; seeds stay below).
targets=(
  "height_png 8192" "height_pgm 4096" "height_pfm 4096" "height_asc 4096"
  "height_raw 4096" "env_hdr 8192" "env_exr 16384" "pfm_image 4096" "scene 4096"
)

t0=$SECONDS
mkdir -p "$build"
CC=clang cmake -S . -B "$build" -DHFS_FUZZ=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DHFS_IO_STB_HEADER_ONLY=ON >"$build/fuzz-configure.log" 2>&1 ||
  { cat "$build/fuzz-configure.log" >&2; exit 1; }
cmake --build "$build" -j"$(nproc)" --target hfs_fuzz >/dev/null ||
  { cmake --build "$build" -j1 --target hfs_fuzz >&2; exit 1; }
echo "fuzz: built ${#targets[@]} targets in $((SECONDS - t0)) s; ${secs} s each, $jobs at a time"

export UBSAN_OPTIONS=print_stacktrace=1

run_one() { # name max_len
  local t=$1 len=$2 bin="$build/tests/fuzz_$1"
  local scratch="$build/fuzz-scratch/$t" art="$build/fuzz-artifacts/$t" log="$build/fuzz-logs/$t.log"
  local dict="tests/fuzz/dict/$t.dict" regress=() tmp
  rm -rf "$scratch" "$art"
  mkdir -p "$scratch" "$art" "$(dirname "$log")"
  cp tests/fuzz/corpus/"$t"/* "$scratch"/
  [ -d "tests/fuzz/regressions/$t" ] && regress=("tests/fuzz/regressions/$t")
  # -malloc_limit_mb: no input of max_len bytes needs 512 MB (the largest
  # legitimate case, an 8 KB 1-bit PNG of 67 Mpixels, takes 270 MB of
  # heights), so a larger single allocation means a loader believed a
  # header's claim before seeing the data: a finding, like a crash.
  local args=(-max_total_time="$secs" -max_len="$len" -timeout=10 -rss_limit_mb=2048
              -malloc_limit_mb=512 -artifact_prefix="$art/" -print_final_stats=1)
  [ -f "$dict" ] && args+=(-dict="$dict")
  # The targets write each input to a file (the loaders take paths): a
  # private folder on tmpfs where there is one.
  tmp=$(mktemp -d "$( [ -w /dev/shm ] && echo /dev/shm || echo "${TMPDIR:-/tmp}")/hfs-fuzz-$t.XXXXXX")
  # New inputs go to the first folder only: the scratch copy.
  local rc=0
  TMPDIR="$tmp" "$bin" "${args[@]}" "$scratch" "${regress[@]}" >"$log" 2>&1 || rc=$?
  echo "$rc" >"$log.rc"
  rm -rf "$tmp"
}

summary() { # name -> one line
  local t=$1 log="$build/fuzz-logs/$1.log" rc execs cov ft corp secs_run
  rc=$(cat "$log.rc")
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  secs_run=$(sed -n 's/.*Done \([0-9]*\) runs in \([0-9]*\) second.*/\2/p' "$log" | tail -1)
  cov=$(grep -o 'cov: [0-9]*' "$log" | tail -1 | cut -d' ' -f2)
  ft=$(grep -o 'ft: [0-9]*' "$log" | tail -1 | cut -d' ' -f2)
  corp=$(grep -o 'corp: [0-9]*' "$log" | tail -1 | cut -d' ' -f2)
  local seeds
  seeds=$(find "tests/fuzz/corpus/$t" -type f | wc -l)
  if [ "$rc" = 0 ]; then
    printf '%-11s ok    %9s execs in %3s s  cov %5s  ft %5s  corpus %4s (seeds %s)\n' \
      "$t" "${execs:-?}" "${secs_run:-?}" "${cov:-?}" "${ft:-?}" "${corp:-?}" "$seeds"
  else
    local crash
    crash=$(sed -n 's/.*Test unit written to \(.*\)$/\1/p' "$log" | tail -1)
    printf '%-11s FAIL  exit %s: %s\n' "$t" "$rc" \
      "$(grep -m1 -E 'ERROR: |SUMMARY: |runtime error|fuzz contract broken|ALARM|out-of-memory' "$log" || echo 'see log')"
    printf '%-11s       reproducer: %s\n' "" "${crash:-none written}"
    printf '%-11s       log: %s\n' "" "$log"
    return 1
  fi
}

running=0
for entry in "${targets[@]}"; do
  set -- $entry
  run_one "$1" "$2" &
  running=$((running + 1))
  if [ "$running" -ge "$jobs" ]; then
    wait -n || true
    running=$((running - 1))
  fi
done
wait || true

failed=0
for entry in "${targets[@]}"; do
  set -- $entry
  summary "$1" || failed=1
done
echo "fuzz: $((SECONDS - t0)) s in all"
if [ "$failed" -ne 0 ]; then
  echo "fuzz: FAILED — copy each reproducer to tests/fuzz/regressions/<target>/ and fix the code" >&2
  exit 1
fi
