#!/usr/bin/env bash
# GLES per-pass times of several builds side by side: each round runs
# `gles_bench --size SIZE --lights both --path slice --frames FRAMES --cold`
# (the fractal25 scene, every pass run) once per build, the builds in turn
# (drift on a shared machine hits all), then prints each pass's and the
# frame wall's median over the rounds (ms) as a Markdown table.
# usage: tools/bench_passes.sh SIZE ROUNDS FRAMES BUILD...
set -euo pipefail
S=${1:?usage: bench_passes.sh SIZE ROUNDS FRAMES BUILD...}
R=${2:?usage: bench_passes.sh SIZE ROUNDS FRAMES BUILD...}
F=${3:?usage: bench_passes.sh SIZE ROUNDS FRAMES BUILD...}
shift 3
[ $# -gt 0 ] || { echo "bench_passes.sh: no build given" >&2; exit 2; }
for _ in $(seq "$R"); do
    for b in "$@"; do
        "$b/tests/gles_bench" --size "$S" --lights both --path slice --frames "$F" --cold 2>&1 |
            awk -v B="$b" '/^  (env|far|transfer|keyfactor|shade) / {v[$1] = $2}
                           /^  sky occlusion / {v["sky"] = $3}
                           /frame wall/ {w = $3}
                           END {print B, v["env"], v["far"], v["transfer"] + 0, v["sky"] + 0,
                                v["keyfactor"], v["shade"], w}'
    done
done | awk '
    { n[$1]++; for (c = 2; c <= 8; ++c) x[$1, c, n[$1]] = $c; if (!($1 in seen)) { seen[$1] = 1; order[k++] = $1 } }
    function median(b, c,    m, i, j, t, a) {
        m = n[b]; for (i = 1; i <= m; ++i) a[i] = x[b, c, i]
        for (i = 2; i <= m; ++i) { t = a[i]; for (j = i - 1; j >= 1 && a[j] > t; --j) a[j + 1] = a[j]; a[j + 1] = t }
        return m % 2 ? a[(m + 1) / 2] : 0.5 * (a[m / 2] + a[m / 2 + 1])
    }
    END {
        print "| build | env | far | transfer | sky occlusion | keyfactor | shade | frame wall |"
        print "|---|---|---|---|---|---|---|---|"
        for (i = 0; i < k; ++i) {
            b = order[i]; line = "| " b
            for (c = 2; c <= 8; ++c) line = line sprintf(" | %.2f", median(b, c))
            print line " |"
        }
    }'
