# Ground truth (runtime/truth/) and the unshadowed normalizer.
hfs_add_test(test_truth_geom SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/test_truth_geom.c
             LIBS hfs_truth LABEL unit TIMEOUT 120)
hfs_add_test(test_truth_render SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/test_truth_render.c
             LIBS hfs_truth LABEL unit TIMEOUT 300)
# The same with local (sphere) lights: over a plane, beside a wall.
hfs_add_test(test_truth_local SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/test_truth_local.c
             LIBS hfs_truth LABEL unit TIMEOUT 300)
# Timing of the ground truth (not a test): see the header of bench_truth.c.
add_executable(bench_truth ${CMAKE_CURRENT_SOURCE_DIR}/bench_truth.c)
target_link_libraries(bench_truth PRIVATE hfs_truth)
# SPEC error metrics (runtime/renderer/metrics.c) on hand-worked distributions.
hfs_add_test(test_metrics SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/test_metrics.c
             LIBS hfshade_lib m LABEL unit TIMEOUT 30)
# Indirect light in the truth: first-hit rays, flat plane, wall closed form,
# white furnace (test_truth_bounce.c).
hfs_add_test(test_truth_bounce SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/test_truth_bounce.c
             LIBS hfs_truth LABEL unit TIMEOUT 300)
# The 3-D view's camera and the truth's ray-cast view, its sky turned by
# env-rotate (test_truth_view.c).
hfs_add_test(test_truth_view SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/test_truth_view.c
             LIBS hfs_truth LABEL unit TIMEOUT 120)
# The truth of an environment map (runtime/truth/truth_envmap.c): constant, SH,
# disk-as-key-light, flat, rotation, from_env, gloss, bad maps, convergence.
hfs_add_test(test_truth_envmap SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/test_truth_envmap.c
             LIBS hfshade_lib m LABEL unit TIMEOUT 300)
# The same end to end through hfshade and the scene layer (truth-env key).
add_test(NAME truth_envmap_cli
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/truth_envmap_cli.sh
                 $<TARGET_FILE:hfshade> $<TARGET_FILE:hfgen> ${PROJECT_SOURCE_DIR}/data)
set_tests_properties(truth_envmap_cli PROPERTIES LABELS io TIMEOUT 120)
