# The sun of the GIS commands (issue 39; tools/solar.cmake, hfs_solar): NOAA's
# solar position against Meeus's worked examples and SPA's published example,
# its invariants, the ISO 8601 date-time parser, and the ESRA clear-sky model
# against hand-computed values (test_solar.c; no GDAL, no GL).
hfs_add_test(test_solar SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/test_solar.c
             LIBS hfs_solar m LABEL unit TIMEOUT 60)
