# display.cmake — the board displays (board/display.h, frame_image.h,
# overlay.h).
#   test_display_frame      frame_image == the PNG writer's bytes (rows
#                           reversed), overlay glyph pixels, fit ("unit")
#   test_display_headless   numbered PNGs decode to the presented pixels,
#                           canvas scaling, refusals and messages ("unit")
#   test_display_x11        own Xvfb, GLES render of a shadowed scene,
#                           window captured with XGetImage == the picture
#                           byte for byte at 1:1 and 2x ("gl"; 77 without
#                           Xvfb or GLES); _es30 / _sse41 under
#                           MESA_GLES_VERSION_OVERRIDE=3.0 /
#                           GALLIUM_OVERRIDE_CPU_CAPS=sse4.1
#   test_display_kms_nodev  no /dev/dri: "kms" fails with its one line
#                           ("gl"; 77 where a card exists)
#   test_display_kms_smoke  real KMS: 120 page-flipped frames ("gl"; 77
#                           without /dev/dri/card*, i.e. here)
# Tests run in this build directory and leave their PNGs there (each x11
# variant writes the same names: the last one run wins).
# Sanitizer builds run the GL ones with tests/lsan.supp (Mesa/LLVM leaks).

if(TARGET hfs_display)
  hfs_add_test(test_display_frame LABEL unit TIMEOUT 60
               SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_display_frame.c
               LIBS hfs_display PkgConfig::HFS_PNG m)
  hfs_add_test(test_display_headless LABEL unit TIMEOUT 60
               SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_display_headless.c
               LIBS hfs_display PkgConfig::HFS_PNG)

  add_executable(test_display_kms ${CMAKE_CURRENT_LIST_DIR}/test_display_kms.c)
  target_link_libraries(test_display_kms PRIVATE hfs_display)
  set(hfs_display_gl_tests test_display_kms_nodev test_display_kms_smoke)
  add_test(NAME test_display_kms_nodev COMMAND test_display_kms nodev)
  add_test(NAME test_display_kms_smoke COMMAND test_display_kms smoke)
  set_tests_properties(test_display_kms_nodev test_display_kms_smoke PROPERTIES
                       SKIP_RETURN_CODE 77 LABELS gl TIMEOUT 60)

  # The same pkg-config check as board/display.cmake: found there means the
  # x11 backend was built.  The test itself talks X too (a second client).
  pkg_check_modules(HFS_TEST_X11 IMPORTED_TARGET x11)
  if(HFS_TEST_X11_FOUND)
    hfs_add_test(test_display_x11 LABEL gl TIMEOUT 180
                 SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_display_x11.c
                 LIBS hfs_display hfshade_lib hfs_terrain_gen PkgConfig::HFS_TEST_X11
                      PkgConfig::HFS_PNG m)
    # As the other gl tests: also on an ES 3.0 context and without AVX.
    add_test(NAME test_display_x11_es30 COMMAND test_display_x11)
    add_test(NAME test_display_x11_sse41 COMMAND test_display_x11)
    set_tests_properties(test_display_x11_es30 test_display_x11_sse41 PROPERTIES
                         SKIP_RETURN_CODE 77 LABELS gl TIMEOUT 180)
    set_tests_properties(test_display_x11_es30 PROPERTIES
                         ENVIRONMENT MESA_GLES_VERSION_OVERRIDE=3.0)
    set_tests_properties(test_display_x11_sse41 PROPERTIES
                         ENVIRONMENT GALLIUM_OVERRIDE_CPU_CAPS=sse4.1)
    list(APPEND hfs_display_gl_tests test_display_x11 test_display_x11_es30
         test_display_x11_sse41)
  endif()

  if(HFS_SANITIZE)
    foreach(t IN LISTS hfs_display_gl_tests)
      set_property(TEST ${t} APPEND PROPERTY ENVIRONMENT
                   "LSAN_OPTIONS=suppressions=${CMAKE_CURRENT_LIST_DIR}/lsan.supp:print_suppressions=0")
    endforeach()
  endif()
endif()
