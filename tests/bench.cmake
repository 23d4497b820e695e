# bench.cmake — hfbench (issue 5): its decisions on made-up numbers (unit)
# and a small end-to-end sweep on the CPU backend (cli): CSV rows, plots
# when gnuplot is there, the truth cache reused on a second run.
hfs_add_test(test_bench_front SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_bench_front.c
             ${PROJECT_SOURCE_DIR}/tools/bench_front.c ${PROJECT_SOURCE_DIR}/tools/bench_sweep.c
             LIBS hfshade_lib hfshade_scene LABEL unit)
target_include_directories(test_bench_front PRIVATE ${PROJECT_SOURCE_DIR}/tools)
add_test(NAME hfbench_smoke
         COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/hfbench_smoke.sh $<TARGET_FILE:hfbench>)
set_tests_properties(hfbench_smoke PROPERTIES LABELS io TIMEOUT 300)
