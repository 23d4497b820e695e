# plan.cmake — the frame planner (issue 6): its decisions on a small graph.
hfs_add_test(test_frame_plan SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_frame_plan.c
             LIBS hfs_base LABEL unit)
target_include_directories(test_frame_plan PRIVATE ${PROJECT_SOURCE_DIR}/runtime)
