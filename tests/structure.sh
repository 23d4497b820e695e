#!/bin/bash
# structure.sh — the library stands alone (issue 14): no file under runtime/
# includes a header of board/ (by path or by a board header's name), and
# the hfshade tool's link line names no board library.
#   tests/structure.sh SOURCE_DIR BUILD_DIR
set -u
src=${1:?usage: structure.sh SOURCE_DIR BUILD_DIR}
build=${2:?usage: structure.sh SOURCE_DIR BUILD_DIR}
fail=0
board_headers=$(cd "$src/board" && ls *.h | sed 's/[.]/[.]/g' | paste -sd'|')
hits=$(grep -rnE "^[[:space:]]*#[[:space:]]*include[[:space:]]*[<\"]([^>\"]*board/|($board_headers)[>\"])" \
       "$src/runtime" --include='*.c' --include='*.h' || true)
if [ -n "$hits" ]; then
    echo "structure: runtime/ includes board/ headers:"
    echo "$hits"
    fail=1
fi
link=$(find "$build" -path '*CMakeFiles/hfshade.dir/link.txt' | head -1)
if [ -z "$link" ]; then
    echo "structure: no link line for hfshade under $build"
    fail=1
elif grep -qE "libhfs_(display|input|kiosk|board)[^ ]*[.]a|board/" "$link"; then
    echo "structure: hfshade links a board library: $(cat "$link")"
    fail=1
fi
[ $fail = 0 ] && echo "structure: runtime/ includes nothing from board/; hfshade links no board library"
exit $fail
