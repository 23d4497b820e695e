# The hfshade command-line tool.
add_executable(hfshade ${CMAKE_CURRENT_SOURCE_DIR}/hfshade.c ${CMAKE_CURRENT_SOURCE_DIR}/cli_view.c
               ${CMAKE_CURRENT_SOURCE_DIR}/cli_picture.c
               ${CMAKE_CURRENT_SOURCE_DIR}/cli_query.c ${CMAKE_CURRENT_SOURCE_DIR}/cli_envmap.c
               ${CMAKE_CURRENT_SOURCE_DIR}/cli_compare.c ${CMAKE_CURRENT_SOURCE_DIR}/cli_gis.c
               ${CMAKE_CURRENT_SOURCE_DIR}/cli_tiles.c ${CMAKE_CURRENT_SOURCE_DIR}/cli_render_job.c
               ${CMAKE_CURRENT_SOURCE_DIR}/cli_help.c ${CMAKE_CURRENT_SOURCE_DIR}/cli_frames.c)
target_link_libraries(hfshade PRIVATE hfshade_lib hfshade_io hfshade_scene hfs_gl
                      hfs_envmap hfs_cli_usage hfs_gis_core)

# Deterministic procedural height fields for tests and benchmarks: the
# generators (one definition for hfgen, tests and benchmarks) and the tool.
add_library(hfs_terrain_gen STATIC ${CMAKE_CURRENT_SOURCE_DIR}/terrain_gen.c)
target_include_directories(hfs_terrain_gen PUBLIC ${CMAKE_CURRENT_SOURCE_DIR})
target_link_libraries(hfs_terrain_gen PUBLIC m)
add_executable(hfgen ${CMAKE_CURRENT_SOURCE_DIR}/hfgen.c)
target_link_libraries(hfgen PRIVATE hfshade_io hfs_terrain_gen hfs_sky_gen hfs_cli_usage m)

# Synthetic skies (gradient + disks + noise) for hfgen sky, the
# decomposition tests and the tracking benchmark.
add_library(hfs_sky_gen STATIC ${CMAKE_CURRENT_SOURCE_DIR}/sky_gen.c)
target_include_directories(hfs_sky_gen PUBLIC ${CMAKE_CURRENT_SOURCE_DIR})
target_link_libraries(hfs_sky_gen PUBLIC m)
add_executable(bench_env ${CMAKE_CURRENT_SOURCE_DIR}/bench_env.c)
target_link_libraries(bench_env PRIVATE hfs_envmap hfs_sky_gen hfshade_io hfs_cli_usage m)
if(TARGET hfshade_gdal)
  target_link_libraries(hfshade PRIVATE hfshade_gdal hfs_gis_gdal)
endif()
