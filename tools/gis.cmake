# The GIS commands' code (issue 39, tools/gis/; `hfshade svf | horizon |
# openness | sun | insolation`, tools/cli_gis.c): hfs_gis_core holds the
# arithmetic, the renderer plumbing (horizons; the sun's renders,
# gis_sun.c, on hfs_solar) and the output group, with no GDAL (the unit
# test tests/test_gis_math.c links it); hfs_gis_gdal the DEM on its own
# grid, the GeoTIFF writers (whole, and window by window) and the commands
# (whole, and streamed: gis_stream.c), where GDAL is found (gdal.cmake).
add_library(hfs_gis_core STATIC ${CMAKE_CURRENT_LIST_DIR}/gis/gis_math.c
            ${CMAKE_CURRENT_LIST_DIR}/gis/gis_resample.c ${CMAKE_CURRENT_LIST_DIR}/gis/gis_horizons.c
            ${CMAKE_CURRENT_LIST_DIR}/gis/gis_products.c ${CMAKE_CURRENT_LIST_DIR}/gis/gis_outputs.c
            ${CMAKE_CURRENT_LIST_DIR}/gis/gis_sun.c ${CMAKE_CURRENT_LIST_DIR}/gis/gis_sky_map.c
            ${CMAKE_CURRENT_LIST_DIR}/gis/gis_sweep.c
            ${CMAKE_CURRENT_LIST_DIR}/gis/gis_sweep_blocks.c)
target_include_directories(hfs_gis_core PUBLIC ${CMAKE_CURRENT_LIST_DIR}/gis)
target_link_libraries(hfs_gis_core PUBLIC hfshade_lib hfshade_io hfs_solar m)
if(TARGET hfshade_gdal)
  add_library(hfs_gis_gdal STATIC ${CMAKE_CURRENT_LIST_DIR}/gis/gis_dem.c
              ${CMAKE_CURRENT_LIST_DIR}/gis/gis_raster.c ${CMAKE_CURRENT_LIST_DIR}/gis/gis_command.c
              ${CMAKE_CURRENT_LIST_DIR}/gis/gis_sun_command.c ${CMAKE_CURRENT_LIST_DIR}/gis/gis_run.c
              ${CMAKE_CURRENT_LIST_DIR}/gis/gis_lit.c ${CMAKE_CURRENT_LIST_DIR}/gis/gis_stream.c
              ${CMAKE_CURRENT_LIST_DIR}/gis/gis_raster_stream.c ${CMAKE_CURRENT_LIST_DIR}/gis/gis_tiles.c
              ${CMAKE_CURRENT_LIST_DIR}/gis/gis_tiles_merge.c
              ${CMAKE_CURRENT_LIST_DIR}/gis/gis_horizon_files.c)
  # the tiles' manifest is INI, read by the scene's reader (libinih)
  pkg_check_modules(HFS_GIS_INIH REQUIRED IMPORTED_TARGET inih)
  target_link_libraries(hfs_gis_gdal PUBLIC hfs_gis_core hfshade_gdal PkgConfig::HFS_GIS_INIH)
endif()
