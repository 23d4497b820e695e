# hfs_shared: algorithm code every backend uses — azimuth swaths and their
# visibility (visibility.c: NS09 Legendre and SN08 wedge tables), the height
# pyramid's layout (pyramid_layout.c), a local light seen from a receiver
# (local_geometry.c), what a key light and the environment become before a
# frame (key_setup.c), shadow height maps (shm.c).  Neutral names: neither the CPU
# reference nor the GLES path owns them.
add_library(hfs_shared STATIC
  ${CMAKE_CURRENT_SOURCE_DIR}/visibility.c
  ${CMAKE_CURRENT_SOURCE_DIR}/pyramid_layout.c
  ${CMAKE_CURRENT_SOURCE_DIR}/local_geometry.c
  ${CMAKE_CURRENT_SOURCE_DIR}/key_setup.c
  ${CMAKE_CURRENT_SOURCE_DIR}/slice_light.c
  ${CMAKE_CURRENT_SOURCE_DIR}/split_horizon.c # split horizons' rules (issue 15)
  ${CMAKE_CURRENT_SOURCE_DIR}/env_open.c      # an env map's open sky (issue 17)
  ${CMAKE_CURRENT_SOURCE_DIR}/env_map_slices.c
  ${CMAKE_CURRENT_SOURCE_DIR}/objects.c       # objects above the field (issue 19)
  ${CMAKE_CURRENT_SOURCE_DIR}/shm.c)          # shadow height maps (issue 19)
target_compile_definitions(hfs_shared PRIVATE HFS_BUILDING_LIBRARY)
target_include_directories(hfs_shared PUBLIC ${CMAKE_CURRENT_SOURCE_DIR})
target_link_libraries(hfs_shared PUBLIC hfs_base hfs_sh)

# hfs_cpu: the CPU reference renderer (DESIGN.md in double precision):
# height pyramid, multi-scale horizons, shading.
# Included from runtime/CMakeLists.txt after sh.cmake (needs hfs_sh).
add_library(hfs_cpu STATIC
  ${CMAKE_CURRENT_SOURCE_DIR}/cpu_pyramid.c
  ${CMAKE_CURRENT_SOURCE_DIR}/cpu_horizon.c
  ${CMAKE_CURRENT_SOURCE_DIR}/cpu_render.c
  ${CMAKE_CURRENT_SOURCE_DIR}/cpu_render_setup.c
  ${CMAKE_CURRENT_SOURCE_DIR}/cpu_far_grid.c  # split horizons' far part (issue 15)
  ${CMAKE_CURRENT_SOURCE_DIR}/cpu_bounce.c
  ${CMAKE_CURRENT_SOURCE_DIR}/cpu_local.c     # local lights (issue 4)
  ${CMAKE_CURRENT_SOURCE_DIR}/cpu_points.c)   # points above the field (issue 19)
target_compile_definitions(hfs_cpu PRIVATE HFS_BUILDING_LIBRARY)
target_include_directories(hfs_cpu PUBLIC ${CMAKE_CURRENT_SOURCE_DIR})
target_link_libraries(hfs_cpu PUBLIC hfs_shared hfs_base hfs_sh)
