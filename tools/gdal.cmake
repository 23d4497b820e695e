# hfshade_gdal (issue 20): the DEMs people have through GDAL (Debian's
# libgdal-dev), an optional module of the tools, never of the core library.
# Without GDAL the tools build as before and read the library's own formats.
#
# The tools do not link libgdal: gdal/gdal_lazy.c loads it on the first
# GDAL call (gdal_lazy.h: linked, its ~110 libraries made every start of
# hfshade cost 88 ms instead of 10).  hfshade_gdal takes GDAL's headers
# and the soname to load; the packages name the library in Depends
# (cmake/package.cmake), since dpkg-shlibdeps no longer sees it.
find_package(GDAL QUIET)
if(GDAL_FOUND)
  # The soname to load: the library file's own (objdump, binutils, which
  # the compiler brings), else the file's name.
  get_target_property(hfs_gdal_file GDAL::GDAL LOCATION)
  get_filename_component(hfs_gdal_file "${hfs_gdal_file}" REALPATH)
  execute_process(COMMAND objdump -p "${hfs_gdal_file}" OUTPUT_VARIABLE hfs_gdal_dyn ERROR_QUIET)
  if(hfs_gdal_dyn MATCHES "SONAME +([^\n ]+)")
    set(hfs_gdal_soname "${CMAKE_MATCH_1}")
  else()
    get_filename_component(hfs_gdal_soname "${hfs_gdal_file}" NAME)
  endif()
  set(HFS_GDAL_SONAME "${hfs_gdal_soname}" CACHE INTERNAL "the GDAL library the tools load")
  set(HFS_GDAL_FILE "${hfs_gdal_file}" CACHE INTERNAL "its file, for the packages' Depends")
  set(HFS_GDAL_VERSION "${GDAL_VERSION}" CACHE INTERNAL "its version, the packages' minimum")
  add_library(hfshade_gdal STATIC ${CMAKE_CURRENT_SOURCE_DIR}/gdal/height_gdal.c
              ${CMAKE_CURRENT_SOURCE_DIR}/gdal/geotiff_write.c
              ${CMAKE_CURRENT_SOURCE_DIR}/gdal/gdal_lazy.c)
  # (the imported target is this folder's: its headers taken by value)
  get_target_property(hfs_gdal_include GDAL::GDAL INTERFACE_INCLUDE_DIRECTORIES)
  target_include_directories(hfshade_gdal PUBLIC ${CMAKE_CURRENT_SOURCE_DIR}/gdal
                             ${hfs_gdal_include})
  target_link_libraries(hfshade_gdal PUBLIC hfshade_io ${CMAKE_DL_LIBS} m)
  target_compile_definitions(hfshade_gdal PUBLIC HFS_HAVE_GDAL
                             PRIVATE HFS_GDAL_SONAME="${hfs_gdal_soname}")
  message(STATUS "GDAL ${GDAL_VERSION}: the tools read GeoTIFF, SRTM .hgt, VRT ... (tools/gdal)")
else()
  unset(HFS_GDAL_SONAME CACHE)
  unset(HFS_GDAL_FILE CACHE)
  unset(HFS_GDAL_VERSION CACHE)
  message(STATUS "GDAL not found: the tools read only the library's own height formats")
endif()
