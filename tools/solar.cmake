# The sun for the GIS commands (issue 39; `hfshade sun`, `hfshade
# insolation`): where it stands (NOAA's solar calculator, with the ISO 8601
# date-time and time-zone parser) and the ESRA clear-sky irradiance as GRASS
# r.sun computes it.  Pure math, no GDAL and no renderer, so the unit test
# (tests/solar.cmake, test_solar) links only this.
add_library(hfs_solar STATIC ${CMAKE_CURRENT_SOURCE_DIR}/gis/solar_position.c
            ${CMAKE_CURRENT_SOURCE_DIR}/gis/clear_sky.c)
target_include_directories(hfs_solar PUBLIC ${CMAKE_CURRENT_SOURCE_DIR}/gis)
target_link_libraries(hfs_solar PUBLIC m)
