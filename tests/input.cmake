# The input layer's logic (board/input.cmake, docs/INPUT.md): no devices,
# label "unit".  The GPIO and evdev sources have their own fragment.
set(HFS_INPUT_DATA ${CMAKE_CURRENT_SOURCE_DIR}/data/input)

hfs_add_test(test_quadrature SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/test_quadrature.c
             LIBS hfs_input LABEL unit TIMEOUT 30)
hfs_add_test(test_debounce SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/test_debounce.c
             LIBS hfs_input LABEL unit TIMEOUT 30)
hfs_add_test(test_input_map SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/test_input_map.c
             LIBS hfs_input m ARGS ${HFS_INPUT_DATA} LABEL unit TIMEOUT 30)
hfs_add_test(test_input_config SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/test_input_config.c
             LIBS hfs_input
             ARGS ${HFS_INPUT_DATA} ${PROJECT_SOURCE_DIR}/board/kiosk.ini
             LABEL unit TIMEOUT 30)
hfs_add_test(test_input_replay SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/test_input_replay.c
             LIBS hfs_input ARGS ${HFS_INPUT_DATA} LABEL unit TIMEOUT 30)
