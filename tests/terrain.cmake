# terrain.cmake — the procedural test scenes (tools/terrain_gen.h), label "unit".
hfs_add_test(test_terrain_gen SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_terrain_gen.c
             LIBS hfs_terrain_gen LABEL unit)
