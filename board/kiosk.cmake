# kiosk.cmake — hfshade-kiosk, the board's program (board/KIOSK.md): the
# scene (hfshade_scene), the renderer (hfshade_lib), a display
# (hfs_display) and the knobs (hfs_input_dev), in one poll loop.
# Included after display.cmake and input*.cmake (fragments go in name order).

# The map (kiosk_map.h: a field larger than the display, lit tile by tile
# ahead of the pan), a library of its own for tests/test_kiosk_map.c.
add_library(hfs_kiosk_map STATIC ${CMAKE_CURRENT_LIST_DIR}/kiosk_map.c
            ${CMAKE_CURRENT_LIST_DIR}/kiosk_map_levels.c)
target_include_directories(hfs_kiosk_map PUBLIC ${CMAKE_CURRENT_LIST_DIR}
                           PRIVATE ${PROJECT_SOURCE_DIR}/runtime/renderer)
target_link_libraries(hfs_kiosk_map PUBLIC hfshade_scene hfshade_lib m)

add_executable(hfshade-kiosk
  ${CMAKE_CURRENT_LIST_DIR}/kiosk_main.c
  ${CMAKE_CURRENT_LIST_DIR}/kiosk_world.c
  ${CMAKE_CURRENT_LIST_DIR}/kiosk_frame.c
  ${CMAKE_CURRENT_LIST_DIR}/kiosk_loop.c
  ${CMAKE_CURRENT_LIST_DIR}/kiosk_check.c
  ${CMAKE_CURRENT_LIST_DIR}/kiosk_stats.c
  ${CMAKE_CURRENT_LIST_DIR}/kiosk_log.c
  ${CMAKE_CURRENT_LIST_DIR}/kiosk_capture.c)
target_link_libraries(hfshade-kiosk PRIVATE hfs_kiosk_map hfs_display hfs_input_dev hfs_capture hfshade_scene
                      hfshade_lib hfs_cli_usage m)
# GeoTIFF, SRTM .hgt, VRT ... DEMs where GDAL is there (tools/gdal.cmake,
# defined after board/: hence the generator expression).
target_link_libraries(hfshade-kiosk PRIVATE $<TARGET_NAME_IF_EXISTS:hfshade_gdal>)
