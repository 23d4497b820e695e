# The GIS horizons (issue 39): hfs_renderer_horizons on the three backends
# against the truth's exact horizons, a tilted plane, the search radius and
# the invariances (scale, mirror, a non-square field).
hfs_add_test(test_horizons SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_horizons.c
             LIBS hfshade_lib hfs_terrain_gen hfs_gl m LABEL gl ARGS 61 47)
