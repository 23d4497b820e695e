# Tests of hfshade_io (label "io"): loaders against independently written
# files, writers, hole filling, damaged inputs and the broken-file corpus.
if(TARGET hfshade_io)
  hfs_add_test(test_io_height LABEL io TIMEOUT 300 SOURCES test_io_height.c
               LIBS hfshade_io PkgConfig::HFS_PNG)
  hfs_add_test(test_io_albedo LABEL io TIMEOUT 300 SOURCES test_io_albedo.c
               LIBS hfshade_io PkgConfig::HFS_PNG m)
  hfs_add_test(test_io_fill LABEL io TIMEOUT 300 SOURCES test_io_fill.c LIBS hfshade_io m)
  hfs_add_test(test_io_write LABEL io TIMEOUT 300 SOURCES test_io_write.c
               LIBS hfshade_io PkgConfig::HFS_PNG m)
  if(TARGET PkgConfig::HFS_STB)
    # stb_image_write (the HDR fixture writer) comes from libstb.so.
    hfs_add_test(test_io_envmap LABEL io TIMEOUT 300 SOURCES test_io_envmap.c
                 LIBS hfshade_io hfs_openexrcore PkgConfig::HFS_STB m)
  endif()
  hfs_add_test(test_io_mutate LABEL io TIMEOUT 300 SOURCES test_io_mutate.c LIBS hfshade_io m)
  hfs_add_test(test_io_corpus LABEL io TIMEOUT 300 SOURCES test_io_corpus.c LIBS hfshade_io
               ARGS ${CMAKE_CURRENT_SOURCE_DIR}/data/broken)
  hfs_add_test(test_io_fixtures LABEL io TIMEOUT 300 SOURCES test_io_fixtures.c LIBS hfshade_io m
               ARGS ${CMAKE_CURRENT_SOURCE_DIR}/data/io)
endif()

# Fuzz targets and the replay of their seeds and former crashes: fuzz.cmake.
