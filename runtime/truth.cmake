# hfs_truth: the brute-force ground truth (exact horizons, exact rays against
# the bilinear surface) and the exact unshadowed normalizer.  DESIGN.md,
# "Ground truth".  Included from runtime/CMakeLists.txt.
add_library(hfs_truth STATIC
  ${CMAKE_CURRENT_SOURCE_DIR}/truth.c
  ${CMAKE_CURRENT_SOURCE_DIR}/truth_raycast.c
  ${CMAKE_CURRENT_SOURCE_DIR}/truth_bounce.c
  ${CMAKE_CURRENT_SOURCE_DIR}/truth_gloss.c
  ${CMAKE_CURRENT_SOURCE_DIR}/truth_envmap.c
  ${CMAKE_CURRENT_SOURCE_DIR}/truth_view.c
  ${CMAKE_CURRENT_SOURCE_DIR}/truth_points.c
  ${CMAKE_CURRENT_SOURCE_DIR}/unshadowed.c)
target_compile_definitions(hfs_truth PRIVATE HFS_BUILDING_LIBRARY)
target_include_directories(hfs_truth PUBLIC ${CMAKE_CURRENT_SOURCE_DIR})
target_link_libraries(hfs_truth PUBLIC hfs_shared hfs_base hfs_sh) # objects.c: the views
