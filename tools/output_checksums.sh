#!/usr/bin/env bash
# output_checksums.sh — the byte-identity check of a restructure (issue 14):
# renders a fixed set of scenes on every backend and writes one line per
# render, "NAME SHA256" of the PFM.  Record before a change, check after:
#
#   tools/output_checksums.sh BUILD record checksums.txt
#   ... change, rebuild ...
#   tools/output_checksums.sh BUILD check checksums.txt   # exit 1 on any difference
#
# Scenes: the demo scene (data/demo.ini, 403x344: environment map + sun) on
# gles fp16 at subsample 2 and 1 and on cpu at subsample 1 and 2; hfgen
# cones, fractal and panel (96x96) with an environment, a key light and two
# local lights on gles fp16 subsample 2 and 1, gles fp32, and cpu at
# subsample 1 and 2, gles with the wedge key visibility, and a wide key
# near the pole on it at fp32; the same at 24x24 on truth.
# GLES checksums hold for one machine and driver (llvmpipe's results depend
# on the CPU's vector width): compare records made on the same machine.
set -euo pipefail
BUILD=${1:?usage: output_checksums.sh BUILD record|check FILE}
MODE=${2:?record or check}
FILE=${3:?checksum file}
root="$(cd "$(dirname "$0")/.." && pwd)"
H="$BUILD/tools/hfshade" GEN="$BUILD/tools/hfgen"
w=$(mktemp -d)
trap 'rm -rf "$w"' EXIT
sky="3.5449077,0.3,0.8,-0.2,0,0.1,0,0,0,0,0,0,0,0,0,0"
out="$w/sums"
: >"$out"
one() { # NAME ARGS...
    local name=$1; shift
    "$H" render "$@" --pfm "$w/o.pfm" --quiet
    echo "$name $(sha256sum <"$w/o.pfm" | cut -d' ' -f1)" >>"$out"
}
one demo-gles-sub2 "$root/data/demo.ini" --backend gles
one demo-gles-sub1 "$root/data/demo.ini" --backend gles --subsample 1
one demo-cpu "$root/data/demo.ini" --backend cpu --subsample 1
one demo-cpu-sub2 "$root/data/demo.ini" --backend cpu
for t in cones fractal panel; do
    "$GEN" "$t" --size 96x96 -o "$w/$t.pfm" >/dev/null
    "$GEN" "$t" --size 24x24 -o "$w/${t}24.pfm" >/dev/null
    L=(--env-sh "$sky" --key 40,25,2,40 --local 30,40,30,3,200 --local 70,60,18,2,120)
    one "$t-gles-sub2" --height "$w/$t.pfm" "${L[@]}" --backend gles
    one "$t-gles-sub1" --height "$w/$t.pfm" "${L[@]}" --backend gles --subsample 1
    one "$t-gles-fp32" --height "$w/$t.pfm" "${L[@]}" --backend gles --precision fp32
    one "$t-cpu" --height "$w/$t.pfm" "${L[@]}" --backend cpu --subsample 1
    one "$t-cpu-sub2" --height "$w/$t.pfm" "${L[@]}" --backend cpu
    one "$t-gles-wedge" --height "$w/$t.pfm" "${L[@]}" --backend gles --visibility wedge
    one "$t-gles-polekey" --height "$w/$t.pfm" --key 40,80,12,40 --backend gles --visibility wedge \
        --precision fp32
    L24=(--env-sh "$sky" --key 40,25,2,40 --local 8,10,9,1,200)
    one "$t-truth" --height "$w/${t}24.pfm" "${L24[@]}" --backend truth --truth-azimuths 720
done
case $MODE in
record)
    cp "$out" "$FILE"
    echo "output_checksums: recorded $(wc -l <"$out") renders in $FILE"
    ;;
check)
    if diff -u "$FILE" "$out"; then
        echo "output_checksums: all $(wc -l <"$out") renders byte-identical"
    else
        echo "output_checksums: renders differ (above)"
        exit 1
    fi
    ;;
*) echo "output_checksums: MODE must be record or check" >&2; exit 2 ;;
esac
