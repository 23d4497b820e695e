# input_devices.cmake — hfs_input_dev: the input sources that open devices
# (board/DEVICES.md), on top of hfs_input (input.cmake, included before).
#   gpio   libgpiod (pkg-config libgpiod): >= 2 -> input_gpio_v2.c
#          (HFS_GPIOD_V2), 1.x -> input_gpio_v1.c, absent -> input_gpio_none.c
#          ("gpio CHIP: not built", HFS_E_UNSUPPORTED).  v2 is not compiled
#          in CI (Debian 12 ships 1.6.3).
#   evdev  libevdev (required, as for hfs_input)
#   set    input_set.c: the sources of a configuration behind one poll loop

pkg_check_modules(HFS_GPIOD IMPORTED_TARGET libgpiod)
pkg_check_modules(HFS_LIBEVDEV REQUIRED IMPORTED_TARGET libevdev)

if(HFS_GPIOD_FOUND AND HFS_GPIOD_VERSION VERSION_GREATER_EQUAL 2)
  set(HFS_GPIO_BACKEND ${CMAKE_CURRENT_LIST_DIR}/input_gpio_v2.c)
  set(HFS_GPIO_DESC "libgpiod ${HFS_GPIOD_VERSION} (v2 API)")
elseif(HFS_GPIOD_FOUND)
  set(HFS_GPIO_BACKEND ${CMAKE_CURRENT_LIST_DIR}/input_gpio_v1.c)
  set(HFS_GPIO_DESC "libgpiod ${HFS_GPIOD_VERSION} (v1 API)")
else()
  set(HFS_GPIO_BACKEND ${CMAKE_CURRENT_LIST_DIR}/input_gpio_none.c)
  set(HFS_GPIO_DESC "not built (install libgpiod-dev)")
endif()

add_library(hfs_input_dev STATIC
  ${CMAKE_CURRENT_LIST_DIR}/input_gpio.c
  ${HFS_GPIO_BACKEND}
  ${CMAKE_CURRENT_LIST_DIR}/input_evdev.c
  ${CMAKE_CURRENT_LIST_DIR}/input_evdev_libevdev.c
  ${CMAKE_CURRENT_LIST_DIR}/input_set.c)
target_include_directories(hfs_input_dev PUBLIC ${CMAKE_CURRENT_LIST_DIR})
target_link_libraries(hfs_input_dev PUBLIC hfs_input PRIVATE PkgConfig::HFS_LIBEVDEV)
if(HFS_GPIOD_FOUND)
  target_link_libraries(hfs_input_dev PRIVATE PkgConfig::HFS_GPIOD)
  if(HFS_GPIOD_VERSION VERSION_GREATER_EQUAL 2)
    target_compile_definitions(hfs_input_dev PRIVATE HFS_GPIOD_V2=1)
  endif()
endif()
message(STATUS "hfshade: input devices: gpio ${HFS_GPIO_DESC}; evdev libevdev ${HFS_LIBEVDEV_VERSION}")
