# plan.cmake — the frame planner (issue 6): its decisions on a small graph.
hfs_add_test(test_frame_plan SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_frame_plan.c
             LIBS hfs_base LABEL unit)
target_include_directories(test_frame_plan PRIVATE ${PROJECT_SOURCE_DIR}/runtime)
# Planned frames equal from-scratch frames after random edits (GLES; 77
# without a context).  The CI run: 2000 edits on a 24x24 field.
hfs_add_test(test_plan_equal SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_plan_equal.c
             LIBS hfshade_lib hfs_terrain_gen m LABEL gl TIMEOUT 900)
# The cases issue 6 names, through the public frame report (GLES).
hfs_add_test(test_plan_cases SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_plan_cases.c
             LIBS hfshade_lib hfs_terrain_gen m LABEL gl TIMEOUT 300)
# The planner's savings on realistic sequences (a benchmark, not a test):
# build/tests/bench_plan [--frames N] [--size N] (BENCHMARKS.md).
add_executable(bench_plan ${CMAKE_CURRENT_LIST_DIR}/bench_plan.c)
target_link_libraries(bench_plan PRIVATE hfshade_lib hfs_terrain_gen m)
target_include_directories(bench_plan PRIVATE ${PROJECT_SOURCE_DIR}/tools)
