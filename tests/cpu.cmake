# CPU reference renderer (runtime/cpu/): pure math and logic, no GPU.
foreach(t pyramid horizon visibility render)
  hfs_add_test(test_cpu_${t} SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/test_cpu_${t}.c
               LIBS hfs_cpu m LABEL unit TIMEOUT 120)
endforeach()
# Indirect light in the CPU reference against closed forms and the truth.
hfs_add_test(test_cpu_bounce SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/test_cpu_bounce.c
             LIBS hfs_cpu hfs_truth m LABEL unit TIMEOUT 300)
# Turning bounces on never lowers a texel (issue 36): the CPU here, GLES
# as test_bounce_direct_gles (gles.cmake).
hfs_add_test(test_bounce_direct SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/test_bounce_direct.c
             LIBS hfshade_lib hfs_cpu hfs_gl hfs_terrain_gen m ARGS cpu LABEL unit TIMEOUT 120)
# Indirect light against the truth on one scene (not a test):
# build/tests/bench_bounce NAME KEY=VALUE... (tools/bench_bounce.sh).
add_executable(bench_bounce ${CMAKE_CURRENT_SOURCE_DIR}/bench_bounce.c)
target_link_libraries(bench_bounce PRIVATE hfshade_scene hfshade_lib m)
# build/tests/bench_shm NAME KEY=VALUE... (tools/bench_shm.sh): shadow height
# maps against the truth's rays, and their query time (BENCHMARKS.md).
add_executable(bench_shm ${CMAKE_CURRENT_SOURCE_DIR}/bench_shm.c)
target_link_libraries(bench_shm PRIVATE hfshade_scene hfshade_lib m)
target_include_directories(bench_shm PRIVATE ${PROJECT_SOURCE_DIR}/tools)
# build/tests/bench_shm_passes [ROUNDS] [SIZE...]: the SHM's time against the
# horizon path's key-light passes, side by side (BENCHMARKS.md).
add_executable(bench_shm_passes ${CMAKE_CURRENT_SOURCE_DIR}/bench_shm_passes.c)
target_link_libraries(bench_shm_passes PRIVATE hfshade_lib hfs_terrain_gen hfs_gl m)
target_include_directories(bench_shm_passes PRIVATE ${PROJECT_SOURCE_DIR}/tools)
# The gap search's max pyramid and search against brute force (issue 36).
hfs_add_test(test_ray_bound SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/test_ray_bound.c
             LIBS hfs_core m LABEL unit TIMEOUT 60)
# The gap search's reads on a field (not a test): build/tests/bench_ray_bound
# FIELD.pfm [ZS] [PHI] [ELEV] (BENCHMARKS.md "Long shadows of narrow features").
add_executable(bench_ray_bound ${CMAKE_CURRENT_SOURCE_DIR}/bench_ray_bound.c)
target_link_libraries(bench_ray_bound PRIVATE hfs_core hfshade_io m)
