# The tools' GDAL height module (tools/gdal, issue 20): GeoTIFF in UTM and
# in degrees, south-up, SRTM .hgt, VRT, refusals (test_gdal_dem.c).  Only
# where GDAL is installed (tools/install-deps.sh installs it).
if(TARGET hfshade_gdal)
  hfs_add_test(test_gdal_dem SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/test_gdal_dem.c
               LIBS hfshade_gdal LABEL io TIMEOUT 120)
  # Issue 20's must-show: the Jacksboro DEM as geographic GeoTIFFs against
  # its PNG, rendered (test_gdal_jacksboro.c).
  hfs_add_test(test_gdal_jacksboro SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/test_gdal_jacksboro.c
               LIBS hfshade_gdal hfshade_lib ARGS ${PROJECT_SOURCE_DIR}/data LABEL io TIMEOUT 300)
endif()
# Issue 39's GIS commands end to end (hfshade svf | horizon | openness) on
# a geographic DEM with holes: the input's grid, CRS and nodata kept, GLES
# against the truth, conventions, bad inputs (test_gis_cli.c).
hfs_add_test(test_gis_cli SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/test_gis_cli.c
             LIBS hfshade_gdal hfs_gl ARGS $<TARGET_FILE:hfshade> LABEL gl TIMEOUT 120)
add_dependencies(test_gis_cli hfshade)
if(HFS_SANITIZE)
  set_property(TEST test_gis_cli APPEND PROPERTY ENVIRONMENT
               "LSAN_OPTIONS=suppressions=${CMAKE_CURRENT_SOURCE_DIR}/lsan.supp:print_suppressions=0")
endif()
# Issue 39's sun commands end to end (hfshade sun | insolation): a flat DEM
# against the library's sun (beam sin(e), V = 1), a wall's shadow on the
# truth and GLES, GLES against the truth on hills, a day's irradiation
# against the hand sum, a night, bad inputs (test_gis_sun.c).
if(TARGET hfshade_gdal)
  hfs_add_test(test_gis_sun SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/test_gis_sun.c
               LIBS hfshade_gdal hfs_gl hfs_solar ARGS $<TARGET_FILE:hfshade> LABEL gl TIMEOUT 120)
  add_dependencies(test_gis_sun hfshade)
  if(HFS_SANITIZE)
    set_property(TEST test_gis_sun APPEND PROPERTY ENVIRONMENT
                 "LSAN_OPTIONS=suppressions=${CMAKE_CURRENT_SOURCE_DIR}/lsan.supp:print_suppressions=0")
  endif()
endif()
