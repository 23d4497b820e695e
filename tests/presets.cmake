# presets.cmake — the quality presets are the settings hfbench picked
# (docs/bench/pareto-256.csv, made by tools/bench_pareto.sh).
hfs_add_test(test_presets SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_presets.c
             LIBS hfshade_lib ARGS ${PROJECT_SOURCE_DIR}/docs/bench/pareto-256.csv LABEL unit)
# The environment's directions matched to the grid step (hfshade.h
# HFS_NPHI_ENV_MATCHED): the rule and the CPU frame; the GLES frame, also
# after a 2x2 frame on the same renderer (the planner sees the change).
hfs_add_test(test_env_dirs SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_env_dirs.c
             LIBS hfshade_scene hfshade_lib hfs_glctx LABEL unit)
target_include_directories(test_env_dirs PRIVATE ${PROJECT_SOURCE_DIR}/runtime/scene)
add_test(NAME test_env_dirs_gles COMMAND test_env_dirs gles)
set_tests_properties(test_env_dirs_gles PROPERTIES SKIP_RETURN_CODE 77 LABELS gl)
