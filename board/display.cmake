# display.cmake — hfs_display: where the kiosk shows frames (display.h), the
# render-to-picture conversion (frame_image.h) and the text overlay
# (overlay.h).
#   headless  always built (no GL; PNGs through hfshade_io)
#   x11       when pkg-config finds x11 (libx11-dev)
#   kms       when pkg-config finds libdrm and gbm (libdrm-dev, libgbm-dev)
# A backend not built compiles to a stub that answers "display NAME: not
# built (...)" with HFS_E_UNSUPPORTED, so the core needs neither library.
# GL comes from the display's EGL context through the hfs_gl table
# (runtime/gl/gl_api.h) and the embedded shaders (fullscreen.vert,
# display_blit.frag); no libGLESv2 is linked.

pkg_check_modules(HFS_X11 IMPORTED_TARGET x11)
pkg_check_modules(HFS_DRM IMPORTED_TARGET libdrm)
pkg_check_modules(HFS_GBM IMPORTED_TARGET gbm)

add_library(hfs_display STATIC
  ${CMAKE_CURRENT_LIST_DIR}/display.c
  ${CMAKE_CURRENT_LIST_DIR}/display_gl.c
  ${CMAKE_CURRENT_LIST_DIR}/display_headless.c
  ${CMAKE_CURRENT_LIST_DIR}/display_x11.c
  ${CMAKE_CURRENT_LIST_DIR}/display_kms.c
  ${CMAKE_CURRENT_LIST_DIR}/frame_image.c
  ${CMAKE_CURRENT_LIST_DIR}/overlay.c)
target_include_directories(hfs_display PUBLIC ${CMAKE_CURRENT_LIST_DIR})
target_compile_definitions(hfs_display PRIVATE HFS_BUILDING_LIBRARY)
target_link_libraries(hfs_display PUBLIC hfs_core hfshade_io
                      PRIVATE hfs_gl PkgConfig::HFS_EGL m)

set(hfs_displays "headless")
if(HFS_X11_FOUND)
  target_compile_definitions(hfs_display PRIVATE HFS_HAVE_X11=1)
  target_link_libraries(hfs_display PRIVATE PkgConfig::HFS_X11)
  list(APPEND hfs_displays x11)
endif()
if(HFS_DRM_FOUND AND HFS_GBM_FOUND)
  target_compile_definitions(hfs_display PRIVATE HFS_HAVE_KMS=1)
  target_link_libraries(hfs_display PRIVATE PkgConfig::HFS_DRM PkgConfig::HFS_GBM)
  list(APPEND hfs_displays kms)
endif()
string(REPLACE ";" ", " hfs_displays_msg "${hfs_displays}")
message(STATUS "hfshade: displays: ${hfs_displays_msg}")
