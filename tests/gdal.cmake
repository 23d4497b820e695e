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
# GDAL loaded when first needed (tools/gdal/gdal_lazy.h): the tools do not
# link it, our formats never load it, a library that cannot be loaded is
# one line naming the input (tests/gdal_lazy.sh).
if(TARGET hfshade_gdal AND TARGET hfshade-kiosk)
  add_test(NAME gdal_lazy COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/gdal_lazy.sh
           $<TARGET_FILE:hfshade> $<TARGET_FILE:hfshade-kiosk> $<TARGET_FILE:hfgen>)
  set_tests_properties(gdal_lazy PROPERTIES LABELS io TIMEOUT 120)
endif()
# Issue 39's GIS commands end to end: each test runs `hfshade` on DEMs it
# writes with GDAL and reads the rasters back (tests/gis_cli_util.h); GL:
# exit 77 only when no GL context can be made.  Only where GDAL is.
function(hfs_gis_cli_test name)
  hfs_add_test(${name} SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/${name}.c
               LIBS hfshade_gdal hfs_gl ${ARGN} ARGS $<TARGET_FILE:hfshade> LABEL gl TIMEOUT 120)
  add_dependencies(${name} hfshade)
  if(HFS_SANITIZE)
    set_property(TEST ${name} APPEND PROPERTY ENVIRONMENT
                 "LSAN_OPTIONS=suppressions=${CMAKE_CURRENT_SOURCE_DIR}/lsan.supp:print_suppressions=0")
  endif()
endfunction()
if(TARGET hfshade_gdal)
  # svf | horizon | openness on a geographic DEM with holes: the input's
  # grid, CRS and nodata kept, GLES against the truth, conventions, the
  # render's GeoTIFF on the DEM's grid, bad inputs (test_gis_cli.c).
  hfs_gis_cli_test(test_gis_cli)
  # Item 1: a DEM over the tile size window by window against the whole
  # run: the same bits on the CPU, fp16's level on GLES, computed whole when
  # it cannot stream, bad --tile (test_gis_stream.c).
  hfs_gis_cli_test(test_gis_stream)
  # sun: a flat DEM against the library's sun (beam sin(e), V = 1), a
  # wall's shadow on the truth and GLES, GLES against the truth on hills, a
  # night, bad inputs of sun and insolation (test_gis_sun.c).
  hfs_gis_cli_test(test_gis_sun hfs_solar)
  # insolation: a day's irradiation on a flat DEM against the hand sum, the
  # sky's share on an open slope and against the truth on hills
  # (test_gis_insolation.c).
  hfs_gis_cli_test(test_gis_insolation hfs_solar)
  # insolation --sky-map: a uniform map is the isotropic sky, a sky bright
  # in the north lights north faces, the map's north, GLES against the
  # truth with the map, bad maps (test_gis_sky_cli.c).
  hfs_gis_cli_test(test_gis_sky_cli hfs_solar)
  # Issue 40 item 1: tiles plan | run | merge, jobs by line, a killed job
  # rerun, merge refused while jobs are missing, the mosaic the streamed
  # run's bits; GNU parallel and --resume-failed byte for byte
  # (test_gis_tiles.c).
  hfs_gis_cli_test(test_gis_tiles)
  # Item 2: a single-node Slurm on localhost runs a plan as a job array
  # (tools/slurm/hfshade_tiles.sbatch), the mosaic the local run's byte for
  # byte; skips where Slurm cannot start (tests/slurm_tiles.sh).
  add_test(NAME slurm_tiles COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/slurm_tiles.sh
           $<TARGET_FILE:hfshade> ${CMAKE_SOURCE_DIR})
  set_tests_properties(slurm_tiles PROPERTIES LABELS io TIMEOUT 420 SKIP_RETURN_CODE 77)
  if(HFS_SANITIZE) # the array's jobs inherit it (sbatch exports the environment)
    set_property(TEST slurm_tiles APPEND PROPERTY ENVIRONMENT
                 "LSAN_OPTIONS=suppressions=${CMAKE_CURRENT_SOURCE_DIR}/lsan.supp:print_suppressions=0")
  endif()
endif()
