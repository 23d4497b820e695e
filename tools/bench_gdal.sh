# bench_gdal.sh — what the GIS benches share; sourced (bash), not run.
#   bench_gdal_need [PKG...]  installs gdal-bin, python3-gdal, python3-numpy
#                             and the packages named when any is missing
#                             (apt-get: the benches install their own tools,
#                             the README's set-up does not)
#   bench_jacksboro_workdir REPO
#                             a new temporary folder, removed on exit, as
#                             the current one and $C, holding utm.tif
#                             (bench_jacksboro_utm)
#   bench_jacksboro_utm REPO OUT.tif
#                             data/jacksboro.png as a Float32 GeoTIFF in UTM
#                             16N with 83 m cells (its 3 arc-second grid
#                             taken as square: the DEM the GIS benchmarks
#                             compare on), nodata -32768
#   bench_fractal_utm REPO BUILD N OUT.tif
#                             an `hfgen fractal` field of N x N (BUILD's
#                             hfgen; BUILD under REPO unless absolute) as a
#                             UTM 16N Float32 GeoTIFF with 30 m cells
#                             (SRTM's; tools/bench_dem.py)
#   bench_dem_utm REPO BUILD DEM OUT.tif
#                             DEM by name: jacksboro or fractal:N (the
#                             two above); 2 and a line for another name

bench_gdal_need() {
    local need=() p
    command -v gdal_translate >/dev/null || need+=(gdal-bin)
    /usr/bin/python3 -c "from osgeo import gdal; import numpy" 2>/dev/null ||
        need+=(python3-gdal python3-numpy)
    for p in "$@"; do
        dpkg -s "$p" >/dev/null 2>&1 || need+=("$p")
    done
    if [ ${#need[@]} -gt 0 ]; then
        echo "installing: ${need[*]}" >&2
        DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends \
            "${need[@]}" >&2
    fi
}

bench_jacksboro_workdir() {
    C=$(mktemp -d)
    trap 'rm -rf "$C"' EXIT
    bench_jacksboro_utm "$1" "$C/utm.tif"
    cd "$C"
}

bench_jacksboro_utm() {
    gdal_translate -q -ot Float32 -a_srs EPSG:32616 -a_ullr 733000 4029000 766449 4000448 \
        -a_nodata -32768 "$1/data/jacksboro.png" "$2"
}

bench_fractal_utm() {
    local pfm
    pfm=$(mktemp --suffix=.pfm)
    local b="$1/$2"
    [[ "$2" = /* ]] && b=$2 # an absolute BUILD as it is
    "$b/tools/hfgen" fractal --size "${3}x$3" -o "$pfm" >/dev/null
    /usr/bin/python3 "$1/tools/bench_dem.py" "$pfm" "$4" 30
    rm -f "$pfm"
}

bench_dem_utm() {
    if [ "$3" = jacksboro ]; then
        bench_jacksboro_utm "$1" "$4"
    elif [[ "$3" =~ ^fractal:([0-9]+)$ ]]; then
        bench_fractal_utm "$1" "$2" "${BASH_REMATCH[1]}" "$4"
    else
        echo "$(basename "$0"): DEM '$3' is not jacksboro or fractal:N" >&2
        return 2
    fi
}
