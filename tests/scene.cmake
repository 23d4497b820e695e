# Scene files and flags.
hfs_add_test(test_scene SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/test_scene.c
             LIBS hfshade_scene LABEL unit)
