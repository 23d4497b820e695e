# The GIS horizons (issue 39): hfs_renderer_horizons on the three backends
# against the truth's exact horizons, a tilted plane, the search radius and
# the invariances (scale, mirror, a non-square field).
hfs_add_test(test_horizons SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_horizons.c
             LIBS hfshade_lib hfs_terrain_gen hfs_gl m LABEL gl ARGS 61 47)
# A lit frame over the device's limit in tiles (issue 39): the halo's rule,
# strict-limit tiles against one frame (no seam), the refusals' way out.
hfs_add_test(test_tiled_render SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_tiled_render.c
             LIBS hfshade_lib hfs_terrain_gen hfs_gl m LABEL gl)
target_include_directories(test_tiled_render PRIVATE ${PROJECT_SOURCE_DIR}/runtime/renderer)
