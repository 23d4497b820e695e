#!/usr/bin/env bash
# mutate_hints.sh — the test that last killed each mutant, for mutate.sh -t.
#
#   tools/mutate_hints.sh [REPORT.md ...] > HINTS
#
# Reads markdown tables of mutate.sh's form (| id | what | verdict | first
# failing test | s |; default docs/MUTATION.md) in order and prints one
# "ID TEST" line per mutant that was KILLED, the last table's test winning,
# so a newer report given after MUTATION.md takes precedence.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
[ $# -gt 0 ] || set -- "$root/docs/MUTATION.md"
for f in "$@"; do
    [ -r "$f" ] || { echo "mutate_hints.sh: $f: cannot read the report" >&2; exit 2; }
done
awk -F'|' '
    NF >= 6 && $2 ~ /^ *M[0-9]+ *$/ && $4 ~ /KILLED/ {
        id = $2; t = $5
        gsub(/ /, "", id); sub(/^ +/, "", t); split(t, w, /[ (]/); t = w[1]
        if (!(id in hint)) order[n++] = id
        hint[id] = t
    }
    END { for (i = 0; i < n; ++i) print order[i], hint[order[i]] }' "$@"
