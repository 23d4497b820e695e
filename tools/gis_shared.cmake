# gis_shared.cmake — libhfshade_gis.so.MAJOR (issue 40): the GIS products of
# a DEM in memory (tools/gis/hfshade_gis.h), for the Python module and any
# program that holds its heights already.  The same GDAL-free sources as the
# commands' hfs_gis_core (gis_math, gis_resample, gis_horizons,
# gis_products, gis_sun) and hfs_solar (solar_position, clear_sky) plus
# gis_api.c, the heights' push-pull hole filling (runtime/io/hole_fill.c,
# pure C: the commands fill holes with it), the field's normals and the
# sun's cap (runtime/core/field_geom.c and lights.c, which gis_sun.c takes
# and libhfshade does not export), over libhfshade.so (hfshade_shared).  Hidden visibility: it
# exports exactly the functions hfshade_gis.h marks HFS_GIS_API (tests/install.sh checks it with
# nm -D); it needs libhfshade, libc and libm only.  Installed in the runtime
# component beside libhfshade (cmake/install.cmake).
set(HFS_GIS_DIR ${CMAKE_CURRENT_LIST_DIR}/gis)
add_library(hfshade_gis_shared SHARED
  ${HFS_GIS_DIR}/gis_api.c ${HFS_GIS_DIR}/gis_math.c ${HFS_GIS_DIR}/gis_resample.c
  ${HFS_GIS_DIR}/gis_horizons.c ${HFS_GIS_DIR}/gis_products.c ${HFS_GIS_DIR}/gis_sun.c
  ${HFS_GIS_DIR}/gis_sky_map.c ${HFS_GIS_DIR}/gis_sweep.c
  ${HFS_GIS_DIR}/gis_sweep_blocks.c ${HFS_GIS_DIR}/solar_position.c
  ${HFS_GIS_DIR}/clear_sky.c
  ${PROJECT_SOURCE_DIR}/runtime/io/hole_fill.c ${PROJECT_SOURCE_DIR}/runtime/core/field_geom.c
  ${PROJECT_SOURCE_DIR}/runtime/core/parallel.c ${PROJECT_SOURCE_DIR}/runtime/core/lights.c)
target_include_directories(hfshade_gis_shared PRIVATE ${HFS_GIS_DIR}
                           ${PROJECT_SOURCE_DIR}/runtime/io ${PROJECT_SOURCE_DIR}/runtime/core)
target_compile_definitions(hfshade_gis_shared PRIVATE HFS_GIS_BUILDING_LIBRARY)
target_link_libraries(hfshade_gis_shared PRIVATE hfshade_shared Threads::Threads m)
set_target_properties(hfshade_gis_shared PROPERTIES
  OUTPUT_NAME hfshade_gis
  VERSION ${PROJECT_VERSION}
  SOVERSION ${PROJECT_VERSION_MAJOR}
  LINKER_LANGUAGE C)
if(NOT HFS_SANITIZE)
  target_link_options(hfshade_gis_shared PRIVATE -Wl,--no-undefined -Wl,--as-needed)
endif()
set(HFS_GIS_PUBLIC_HEADERS ${HFS_GIS_DIR}/hfshade_gis.h CACHE INTERNAL "Installed GIS header")
