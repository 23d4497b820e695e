# input.cmake — hfs_input: the input layer's logic, no devices
# (docs/INPUT.md): quadrature decoder, button debounce, the configuration
# file (libinih; event code names through libevdev's name tables, no device
# is opened), the event-to-scene mapping, the replay source and the clock.
# The GPIO and evdev sources build on it in their own fragments.

pkg_check_modules(HFS_INPUT_INIH REQUIRED IMPORTED_TARGET inih)
pkg_check_modules(HFS_INPUT_EVDEV REQUIRED IMPORTED_TARGET libevdev)

add_library(hfs_input STATIC
  ${CMAKE_CURRENT_LIST_DIR}/quadrature.c
  ${CMAKE_CURRENT_LIST_DIR}/debounce.c
  ${CMAKE_CURRENT_LIST_DIR}/input_config.c
  ${CMAKE_CURRENT_LIST_DIR}/input_actions.c
  ${CMAKE_CURRENT_LIST_DIR}/input_map.c
  ${CMAKE_CURRENT_LIST_DIR}/input_replay.c
  ${CMAKE_CURRENT_LIST_DIR}/input_clock.c)
target_include_directories(hfs_input PUBLIC ${CMAKE_CURRENT_LIST_DIR})
target_link_libraries(hfs_input PUBLIC hfs_core hfshade_scene
                      PRIVATE PkgConfig::HFS_INPUT_INIH PkgConfig::HFS_INPUT_EVDEV m)
