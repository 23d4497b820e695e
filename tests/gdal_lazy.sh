#!/usr/bin/env bash
# gdal_lazy.sh — GDAL is loaded when first needed (tools/gdal/gdal_lazy.h):
#   - hfshade and the kiosk do not link libgdal (readelf NEEDED): its ~110
#     libraries made every start 8x slower;
#   - our own formats never load it: a PFM render succeeds with
#     HFS_GDAL_LIBRARY naming a library that does not exist;
#   - a file only GDAL reads, and a GIS command's DEM, give one line that
#     names the input and the library, exit 1, and write nothing, when the
#     library cannot be loaded (missing, or not GDAL: libm);
#   - with the real library the same GeoTIFF loads and renders.
# usage: gdal_lazy.sh HFSHADE KIOSK HFGEN
set -u
HFSHADE=$1 KIOSK=$2 HFGEN=$3
w=$(mktemp -d)
trap 'rm -rf "$w"' EXIT
fails=0
bad() { echo "FAIL: $*"; fails=$((fails + 1)); }
sky="3.5449077,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0"

for exe in "$HFSHADE" "$KIOSK"; do
    if readelf -d "$exe" | grep -q 'NEEDED.*libgdal'; then
        bad "$(basename "$exe") links libgdal: $(readelf -d "$exe" | grep libgdal)"
    else
        echo "ok   $(basename "$exe") does not link libgdal"
    fi
done

"$HFGEN" cones --size 12x10 -o "$w/h.pfm" >/dev/null || { echo "FAIL: hfgen"; exit 1; }
missing=$w/no/libgdal.so.0
if HFS_GDAL_LIBRARY=$missing "$HFSHADE" render --backend cpu --nphi-env 4 --height "$w/h.pfm" \
        --env-sh "$sky" -o "$w/pfm.png" >/dev/null 2>"$w/err" && [ -s "$w/pfm.png" ]; then
    echo "ok   a PFM renders without GDAL"
else
    bad "a PFM render needed GDAL: $(head -2 "$w/err")"
fi

# A GeoTIFF (a render's, written by hfshade with the real library: its
# band 1 is a raster like any DEM's).
"$HFSHADE" render --backend cpu --nphi-env 4 --height "$w/h.pfm" --env-sh "$sky" \
    --geotiff "$w/dem.tif" >/dev/null 2>"$w/err" || bad "GeoTIFF write: $(head -1 "$w/err")"

# expect_refused NAME LIBRARY NEEDLE ARGS...
expect_refused() {
    local name=$1 lib=$2 needle=$3
    shift 3
    rm -f "$w"/out.*
    HFS_GDAL_LIBRARY=$lib "$HFSHADE" "$@" >/dev/null 2>"$w/err"
    local rc=$? lines
    lines=$(wc -l <"$w/err")
    if [ $rc -ne 1 ]; then bad "$name: exit status $rc"
    elif [ "$lines" -ne 1 ]; then bad "$name: $lines lines on stderr: $(cat "$w/err")"
    elif ! grep -qF -- "dem.tif: GDAL ($lib) cannot be loaded" "$w/err" ||
         ! grep -qF -- "$needle" "$w/err"; then bad "$name: message: $(cat "$w/err")"
    elif ls "$w"/out.* >/dev/null 2>&1; then bad "$name: output left behind"
    else echo "ok   $name: $(cat "$w/err")"
    fi
}
expect_refused render-missing "$missing" "cannot open shared object file" \
    render --backend cpu --height "$w/dem.tif" --env-sh "$sky" -o "$w/out.png"
expect_refused svf-missing "$missing" "cannot open shared object file" \
    svf "$w/dem.tif" -o "$w/out.tif"
expect_refused render-not-gdal libm.so.6 "it has no " \
    render --backend cpu --height "$w/dem.tif" --env-sh "$sky" -o "$w/out.png"

if "$HFSHADE" render --backend cpu --nphi-env 4 --height "$w/dem.tif" --env-sh "$sky" \
        -o "$w/tif.png" >/dev/null 2>"$w/err" && [ -s "$w/tif.png" ]; then
    echo "ok   the GeoTIFF renders with GDAL"
else
    bad "the GeoTIFF's render: $(head -1 "$w/err")"
fi
[ $fails = 0 ] && echo "gdal_lazy: PASS"
exit $((fails > 0))
