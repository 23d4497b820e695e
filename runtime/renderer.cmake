# hfshade: the public renderer object over every backend.
add_library(hfshade_lib STATIC
  ${CMAKE_CURRENT_SOURCE_DIR}/renderer.c
  ${CMAKE_CURRENT_SOURCE_DIR}/validate.c
  ${CMAKE_CURRENT_SOURCE_DIR}/view_params.c
  ${CMAKE_CURRENT_SOURCE_DIR}/metrics.c)
target_compile_definitions(hfshade_lib PRIVATE HFS_BUILDING_LIBRARY)
target_include_directories(hfshade_lib PUBLIC ${CMAKE_CURRENT_SOURCE_DIR})
target_link_libraries(hfshade_lib PUBLIC hfs_gles hfs_cpu hfs_truth hfs_sh hfs_base)
set_target_properties(hfshade_lib PROPERTIES OUTPUT_NAME hfshade)
