# presets.cmake — the quality presets are the settings hfbench picked
# (docs/bench/pareto-256.csv, made by tools/bench_pareto.sh).
hfs_add_test(test_presets SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_presets.c
             LIBS hfshade_lib ARGS ${PROJECT_SOURCE_DIR}/docs/bench/pareto-256.csv LABEL unit)
