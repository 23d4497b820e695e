# The GIS commands' arithmetic (issue 39, tools/gis/): conventions, the
# products from horizon angles, r.horizon's names, the nodata rule, the
# sample back to the input's grid, and a V valley through the products on
# the truth and CPU backends (test_gis_math.c; no GDAL, no GL).  The
# commands end to end: test_gis_cli (and test_gis_stream, a DEM over the
# tile size window by window) in gdal.cmake.
hfs_add_test(test_gis_math SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/test_gis_math.c
             LIBS hfs_gis_core m LABEL unit TIMEOUT 60)
# insolation's sky from a map (--sky-map): uniform = isotropic, a
# brute-force sum over the map's pixels, the map's north, bad maps.
hfs_add_test(test_gis_sky_map SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/test_gis_sky_map.c
             LIBS hfs_gis_core m LABEL unit TIMEOUT 60)
# the horizons' sweep (--method sweep): exact along the axes, against the
# CPU backend's exact horizons on oblique azimuths, turns, threads.
hfs_add_test(test_gis_sweep SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/test_gis_sweep.c
             LIBS hfs_gis_core m LABEL unit TIMEOUT 60)
# the windowed sweep's block bounds: never below a line's own bands.
hfs_add_test(test_gis_sweep_blocks SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/test_gis_sweep_blocks.c
             LIBS hfs_gis_core m LABEL unit TIMEOUT 60)
