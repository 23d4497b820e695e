# input_devices.cmake — tests of the device sources (board/DEVICES.md):
# GPIO through a scripted chip, evdev through a fake libevdev table and
# through umockdev (a real libevdev on an emulated /dev/input node), the
# set's losses and back-off, and an end-to-end run on the kernel's gpio-sim
# where the machine offers it (otherwise skipped, exit 77).

hfs_add_test(test_input_gpio
  SOURCES test_input_gpio.c input_gpio_fake.c
  LIBS hfs_input_dev LABEL unit TIMEOUT 30)

hfs_add_test(test_input_evdev
  SOURCES test_input_evdev.c
  LIBS hfs_input_dev LABEL unit TIMEOUT 30)

hfs_add_test(test_input_set
  SOURCES test_input_set.c input_gpio_fake.c
  LIBS hfs_input_dev LABEL unit TIMEOUT 30)

# umockdev: the real libevdev on an emulated node.  Without umockdev-run the
# binary runs bare and exits 77 saying so.  umockdev works by LD_PRELOAD, so
# under ASan the runtime cannot come first: tell ASan not to insist.
find_program(HFS_UMOCKDEV_RUN umockdev-run)
add_executable(test_input_evdev_umockdev test_input_evdev_umockdev.c)
target_link_libraries(test_input_evdev_umockdev PRIVATE hfs_input_dev)
set(HFS_UMOCKDEV_DATA ${CMAKE_CURRENT_SOURCE_DIR}/data/input_dev)
if(HFS_UMOCKDEV_RUN)
  add_test(NAME test_input_evdev_umockdev
           COMMAND ${HFS_UMOCKDEV_RUN} -d ${HFS_UMOCKDEV_DATA}/knob.umockdev
                   -i /dev/input/event9=${HFS_UMOCKDEV_DATA}/knob.ioctl
                   -e /dev/input/event9=${HFS_UMOCKDEV_DATA}/knob.events
                   -- $<TARGET_FILE:test_input_evdev_umockdev>)
else()
  add_test(NAME test_input_evdev_umockdev COMMAND test_input_evdev_umockdev)
endif()
set_tests_properties(test_input_evdev_umockdev PROPERTIES SKIP_RETURN_CODE 77
                     LABELS unit TIMEOUT 30
                     ENVIRONMENT "ASAN_OPTIONS=verify_asan_link_order=0")

hfs_add_test(test_input_gpio_sim
  SOURCES test_input_gpio_sim.c
  LIBS hfs_input_dev LABEL unit TIMEOUT 60)
