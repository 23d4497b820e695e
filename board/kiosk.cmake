# kiosk.cmake — hfshade-kiosk, the board's program (board/KIOSK.md): the
# scene (hfshade_scene), the renderer (hfshade_lib), a display
# (hfs_display) and the knobs (hfs_input_dev), in one poll loop.
# Included after display.cmake and input*.cmake (fragments go in name order).

add_executable(hfshade-kiosk
  ${CMAKE_CURRENT_LIST_DIR}/kiosk_main.c
  ${CMAKE_CURRENT_LIST_DIR}/kiosk_world.c
  ${CMAKE_CURRENT_LIST_DIR}/kiosk_frame.c
  ${CMAKE_CURRENT_LIST_DIR}/kiosk_loop.c
  ${CMAKE_CURRENT_LIST_DIR}/kiosk_check.c
  ${CMAKE_CURRENT_LIST_DIR}/kiosk_stats.c
  ${CMAKE_CURRENT_LIST_DIR}/kiosk_log.c
  ${CMAKE_CURRENT_LIST_DIR}/kiosk_capture.c)
target_link_libraries(hfshade-kiosk PRIVATE hfs_display hfs_input_dev hfs_capture hfshade_scene
                      hfshade_lib hfs_cli_usage m)
# GeoTIFF, SRTM .hgt, VRT ... DEMs where GDAL is there (tools/gdal.cmake,
# defined after board/: hence the generator expression).
target_link_libraries(hfshade-kiosk PRIVATE $<TARGET_NAME_IF_EXISTS:hfshade_gdal>)
