# hfbench: run time against error over quality settings (issue 5).
add_executable(hfbench ${CMAKE_CURRENT_SOURCE_DIR}/hfbench.c
               ${CMAKE_CURRENT_SOURCE_DIR}/bench_scene.c ${CMAKE_CURRENT_SOURCE_DIR}/bench_truth.c
               ${CMAKE_CURRENT_SOURCE_DIR}/bench_sweep.c ${CMAKE_CURRENT_SOURCE_DIR}/bench_front.c)
target_link_libraries(hfbench PRIVATE hfshade_lib hfshade_io hfshade_scene hfs_sh
                      hfs_terrain_gen hfs_cli_usage m)
target_compile_definitions(hfbench PRIVATE HFS_DATA_DIR="${PROJECT_SOURCE_DIR}/data")
