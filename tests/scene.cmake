# Scene files and flags.
hfs_add_test(test_scene SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/test_scene.c
             LIBS hfshade_scene LABEL unit)

# The table of scene keys (runtime/core/scene_keys.h) against its documents and
# its readers: the parser, the renderer's validation, the knob limits.
hfs_add_test(test_scene_keys SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/test_scene_keys.c
             LIBS hfshade_scene hfshade_lib hfs_input m
             ARGS ${PROJECT_SOURCE_DIR}/docs/SCENE.md ${PROJECT_SOURCE_DIR}/../shared/SPEC.md
             LABEL unit TIMEOUT 60)
# Heights checked once per change (hfs_renderer_set_field_serial), CPU backend.
hfs_add_test(test_validate_once SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/test_validate_once.c
             LIBS hfshade_lib m LABEL unit TIMEOUT 60)
