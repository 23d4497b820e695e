#!/usr/bin/env bash
# mutations_check.sh — the mutation list still applies (seconds, in ctest as
# `mutations_apply`): every mutation of LIST (default tools/mutations.txt,
# the format of tools/mutate.sh) has its five fields, a unique ID, a FIND
# that occurs exactly once in its FILE and a REPLACE that differs from it.
# A rewrite that moves the code a mutant targets then fails the suite at
# once, not the nightly tools/mutate.sh (which reports such a mutant as
# STALE and fails).
# usage: tools/mutations_check.sh [LIST]   exit 1 naming each bad line
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
list="${1:-$root/tools/mutations.txt}"
bad=0 n=0
declare -A seen
while IFS= read -r line; do
    case "$line" in ''|'#'*) continue ;; esac
    IFS=$'\t' read -r id file find replace what <<<"$line"
    n=$((n + 1))
    if [ -z "$what" ]; then
        echo "mutations_check: $id: fewer than five TAB-separated fields" >&2; bad=1; continue
    fi
    if [ -n "${seen[$id]:-}" ]; then
        echo "mutations_check: $id: ID used twice" >&2; bad=1
    fi
    seen[$id]=1
    if [ ! -r "$root/$file" ]; then
        echo "mutations_check: $id: $file: no such file" >&2; bad=1; continue
    fi
    if [ "$find" = "$replace" ]; then
        echo "mutations_check: $id: REPLACE equals FIND" >&2; bad=1
    fi
    count=$(FIND="$find" perl -0777 -ne '
        my $f = $ENV{FIND}; $f =~ s/\\t/\t/g; $f =~ s/\\n/\n/g;
        my $n = () = $_ =~ /\Q$f\E/g; print $n;' "$root/$file")
    if [ "$count" != 1 ]; then
        echo "mutations_check: $id: STALE: FIND occurs $count times in $file" >&2; bad=1
    fi
done <"$list"
[ "$n" -gt 0 ] || { echo "mutations_check: $list: no mutations" >&2; exit 1; }
[ "$bad" -eq 0 ] && echo "mutations_check: $n mutations apply"
exit "$bad"
