# plan.cmake — the frame planner (issue 6): its decisions on a small graph.
hfs_add_test(test_frame_plan SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_frame_plan.c
             LIBS hfs_base LABEL unit)
target_include_directories(test_frame_plan PRIVATE ${PROJECT_SOURCE_DIR}/runtime)
# Planned frames equal from-scratch frames after random edits (GLES; 77
# without a context).  The CI run: 2000 edits on a 24x24 field.
hfs_add_test(test_plan_equal SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_plan_equal.c
             LIBS hfshade_lib hfs_terrain_gen m LABEL gl TIMEOUT 900)
