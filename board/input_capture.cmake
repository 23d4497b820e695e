# input_capture.cmake — hfs_capture: camera inputs (docs/CAPTURE.md).  V4L2
# through the kernel header only (linux/videodev2.h, linux-libc-dev), the
# recordings and their replay, the synthetic depth camera, and depth to
# heights (no V4L2 in depth_heights.c).  The [capture NAME] keys
# (capture_config.c) are parsed inside hfs_input, which reads the file.
# Tools: hfs-capture-info DEVICE, hfs-capture-synth DIR.

target_sources(hfs_input PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/capture_config.c
  ${CMAKE_CURRENT_LIST_DIR}/depth_heights.c
  ${CMAKE_CURRENT_LIST_DIR}/camera_env.c
  ${CMAKE_CURRENT_LIST_DIR}/camera_sky.c
  ${CMAKE_CURRENT_LIST_DIR}/capture.c
  ${CMAKE_CURRENT_LIST_DIR}/backoff.c)
target_link_libraries(hfs_input PUBLIC hfshade_io hfs_envmap hfs_sh)

add_library(hfs_capture STATIC
  ${CMAKE_CURRENT_LIST_DIR}/capture_v4l2.c
  ${CMAKE_CURRENT_LIST_DIR}/capture_info.c
  ${CMAKE_CURRENT_LIST_DIR}/capture_record.c
  ${CMAKE_CURRENT_LIST_DIR}/capture_synth.c
  ${CMAKE_CURRENT_LIST_DIR}/capture_synth_sky.c
  ${CMAKE_CURRENT_LIST_DIR}/capture_live.c)
target_include_directories(hfs_capture PUBLIC ${CMAKE_CURRENT_LIST_DIR})
target_link_libraries(hfs_capture PUBLIC hfs_input hfs_core PRIVATE m)

add_executable(hfs-capture-info ${CMAKE_CURRENT_LIST_DIR}/capture_info_main.c)
target_link_libraries(hfs-capture-info PRIVATE hfs_capture hfs_cli_usage)
add_executable(hfs-capture-synth ${CMAKE_CURRENT_LIST_DIR}/capture_synth_main.c)
target_link_libraries(hfs-capture-synth PRIVATE hfs_capture hfs_cli_usage m)
