# hfshade_gdal (issue 20): the DEMs people have through GDAL (Debian's
# libgdal-dev), an optional module of the tools, never of the core library.
# Without GDAL the tools build as before and read the library's own formats.
find_package(GDAL QUIET)
if(GDAL_FOUND)
  add_library(hfshade_gdal STATIC ${CMAKE_CURRENT_SOURCE_DIR}/gdal/height_gdal.c
              ${CMAKE_CURRENT_SOURCE_DIR}/gdal/geotiff_write.c)
  target_include_directories(hfshade_gdal PUBLIC ${CMAKE_CURRENT_SOURCE_DIR}/gdal)
  target_link_libraries(hfshade_gdal PUBLIC hfshade_io GDAL::GDAL m)
  target_compile_definitions(hfshade_gdal PUBLIC HFS_HAVE_GDAL)
  message(STATUS "GDAL ${GDAL_VERSION}: the tools read GeoTIFF, SRTM .hgt, VRT ... (tools/gdal)")
else()
  message(STATUS "GDAL not found: the tools read only the library's own height formats")
endif()
