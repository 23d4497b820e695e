#!/bin/bash
# include_rules_planted.sh — include_rules.sh must catch what it exists for:
# on a copy of the tree, each planted include below, alone, must fail it
# with a line naming the file and the header; the unplanted copy must pass.
#   tests/include_rules_planted.sh SOURCE_DIR
set -u
src=${1:?usage: include_rules_planted.sh SOURCE_DIR}
here=$(cd "$(dirname "$0")" && pwd)
w=$(mktemp -d)
trap 'rm -rf "$w"' EXIT
cp -r "$src/runtime" "$w/runtime"
for other in board tools; do
    mkdir -p "$w/$other"
    (cd "$src/$other" && find . -name '*.h' -exec cp --parents -t "$w/$other/" {} +)
done
if ! out=$(bash "$here/include_rules.sh" "$w"); then
    echo "include_rules_planted: the unplanted copy fails:"
    echo "$out"
    exit 1
fi
# FILE (under runtime/) | the planted line | what the report must say
plants='core/visibility.c|#include "cpu_horizon.h"|core/visibility.c:.*cpu_horizon.h from cpu/
core/sh_free.c|#include "gl_api.h"|core/sh_free.c:.*gl_api.h from gl/
core/lights.h|#include "../scene/scene.h"|core/lights.h:.*scene.h from scene/
truth/truth.c|#include "gles_backend.h"|truth/truth.c:.*gles_backend.h from gles/
truth/truth_view.c|#include "cpu_render_ctx.h"|truth/truth_view.c:.*cpu_render_ctx.h from cpu/
cpu/cpu_render.c|#include <kiosk.h>|cpu/cpu_render.c:.*kiosk.h from board/
gles/pass_shade.c|#include "../../tools/hfstress.h"|gles/pass_shade.c:.*from tools/
sh/sh.c|#include "lights.h"|sh/sh.c:.*lights.h from core/
core/objects.c|#include "no_such_header.h"|core/objects.c:.*no header of runtime'
fail=0
while IFS='|' read -r file line expect; do
    target="$w/runtime/$file"
    [ -e "$target" ] && cp "$target" "$w/keep" || rm -f "$w/keep"
    printf '%s\n' "$line" >>"$target"
    out=$(bash "$here/include_rules.sh" "$w")
    rc=$?
    if [ $rc != 1 ] || ! grep -qE "$expect" <<<"$out"; then
        echo "include_rules_planted: '$line' in runtime/$file was not caught (exit $rc): $out"
        fail=1
    else
        echo "caught: $(grep -E "$expect" <<<"$out" | head -1)"
    fi
    if [ -e "$w/keep" ]; then mv "$w/keep" "$target"; else rm -f "$target"; fi
done <<<"$plants"
[ $fail = 0 ] && echo "include_rules_planted: every planted include was caught"
exit $fail
