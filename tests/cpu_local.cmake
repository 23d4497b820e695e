# Local lights in the CPU reference (runtime/cpu/cpu_local.c, issue 4).
hfs_add_test(test_cpu_local SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/test_cpu_local.c
             LIBS hfshade_lib m LABEL unit TIMEOUT 300)
# The same against the ground truth (a truth render: most of the time).
hfs_add_test(test_cpu_local_truth SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/test_cpu_local_truth.c
             LIBS hfshade_lib m LABEL unit TIMEOUT 300)
# Their building blocks: the Legendre fold, point slopes, cap window, entry
# distance, partial swath against closed forms and brute force.
hfs_add_test(test_cpu_local_parts SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/test_cpu_local_parts.c
             LIBS hfshade_lib m LABEL unit TIMEOUT 120)
# Timing / swath-mode driver (not a test): see the header of test_cpu_local_bench.c.
add_executable(bench_cpu_local ${CMAKE_CURRENT_SOURCE_DIR}/test_cpu_local_bench.c)
target_link_libraries(bench_cpu_local PRIVATE hfshade_lib hfshade_io hfshade_scene)
# The shadow-range test of local lights (lights.h hfs_local_light_open).
hfs_add_test(test_local_open SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/test_local_open.c
             LIBS hfshade_lib hfs_core m LABEL unit TIMEOUT 120)
