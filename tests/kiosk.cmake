# kiosk.cmake — hfshade-kiosk end to end (board/KIOSK.md).
#   kiosk_bad_inputs       missing/broken scene, configuration, replay,
#                          unknown display, usage errors: one line, non-zero
#                          exit, no frame; the shipped example passes
#                          --check ("io"; no GL needed)
#   kiosk_x11_texture      an x11 window (xvfb-run): frames as the shared
#                          renderer's texture, and with --readback; every
#                          event shown ("gl"; 77 without xvfb-run)
#   test_kiosk_replay      scripted knobs move the key light: last frame ==
#                          direct library render, byte for byte ("gl");
#                          _es30 under MESA_GLES_VERSION_OVERRIDE=3.0
#   test_kiosk_amortize    the same with --amortize 1: the last frame, after
#                          the amortized passes caught up, is still the
#                          direct render ("gl")
#   test_kiosk_signals     SIGHUP reload (good and broken scene, a check
#                          process killed by a signal), journal priorities,
#                          SIGTERM exit 0 ("gl")
#   test_kiosk_idle        3 s without events: no frame, < 5% of a core ("gl")
#   test_kiosk_view        a button turns the 3-D view on, knobs turn the
#                          camera: last frame == the library's view ("gl")
#   test_kiosk_example     board/kiosk.ini driving data/demo.ini ("gl")
#   test_kiosk_large       a 2100x40 field (wider than any display) shown
#                          shrunk to 1050x20, equal to the library's render
#                          shrunk in linear light (CPU backend, "io")
# GL tests exit 77 without a GLES context.  Sanitizer builds run the GL ones
# with tests/lsan.supp (Mesa/LLVM leaks only), as tests/gl.cmake does; the
# kiosk they start inherits LSAN_OPTIONS.

if(TARGET hfshade-kiosk)
  add_test(NAME kiosk_bad_inputs
           COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/kiosk_bad_inputs.sh
                   $<TARGET_FILE:hfshade-kiosk> $<TARGET_FILE:hfgen> ${PROJECT_SOURCE_DIR})
  set_tests_properties(kiosk_bad_inputs PROPERTIES LABELS io TIMEOUT 120)

  # Issue 20: the kiosk on an x11 window, frames as the renderer's texture
  # and with --readback (kiosk_x11_texture.sh; 77 without xvfb-run); one of
  # hfs_kiosk_gl_tests below.
  add_test(NAME kiosk_x11_texture
           COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/kiosk_x11_texture.sh
                   $<TARGET_FILE:hfshade-kiosk> $<TARGET_FILE:hfgen>)

  add_executable(test_kiosk ${CMAKE_CURRENT_LIST_DIR}/test_kiosk.c
                            ${CMAKE_CURRENT_LIST_DIR}/kiosk_harness.c)
  target_link_libraries(test_kiosk PRIVATE hfshade_scene hfs_display hfshade_lib
                        PkgConfig::HFS_PNG m)
  add_dependencies(test_kiosk hfshade-kiosk hfgen)
  set(hfs_kiosk_gl_tests test_kiosk_replay test_kiosk_amortize test_kiosk_signals
      test_kiosk_idle test_kiosk_example test_kiosk_view kiosk_x11_texture)
  foreach(mode replay amortize signals idle view)
    add_test(NAME test_kiosk_${mode}
             COMMAND test_kiosk ${mode} $<TARGET_FILE:hfshade-kiosk> $<TARGET_FILE:hfgen>)
  endforeach()
  # As the other gl tests: also on an ES 3.0 context (as on boards).
  add_test(NAME test_kiosk_replay_es30
           COMMAND test_kiosk replay $<TARGET_FILE:hfshade-kiosk> $<TARGET_FILE:hfgen>)
  set_tests_properties(test_kiosk_replay_es30 PROPERTIES
                       ENVIRONMENT MESA_GLES_VERSION_OVERRIDE=3.0)
  list(APPEND hfs_kiosk_gl_tests test_kiosk_replay_es30)
  add_test(NAME test_kiosk_large
           COMMAND test_kiosk large $<TARGET_FILE:hfshade-kiosk> $<TARGET_FILE:hfgen>)
  set_tests_properties(test_kiosk_large PROPERTIES LABELS io TIMEOUT 300)
  add_test(NAME test_kiosk_example
           COMMAND test_kiosk example $<TARGET_FILE:hfshade-kiosk>
                   ${PROJECT_SOURCE_DIR}/data/demo.ini ${PROJECT_SOURCE_DIR}/board/kiosk.ini
                   ${CMAKE_CURRENT_LIST_DIR}/data/kiosk/example_replay.txt)
  set_tests_properties(${hfs_kiosk_gl_tests} PROPERTIES SKIP_RETURN_CODE 77 LABELS gl
                       TIMEOUT 300)
  if(HFS_SANITIZE)
    foreach(t IN LISTS hfs_kiosk_gl_tests)
      set_property(TEST ${t} APPEND PROPERTY ENVIRONMENT
                   "LSAN_OPTIONS=suppressions=${CMAKE_CURRENT_LIST_DIR}/lsan.supp:print_suppressions=0")
    endforeach()
  endif()
  # Issue 13: 100 reloads alternating a good scene and one the renderer refuses;
  # still running, fds and memory flat (tests/kiosk_reload_soak.sh prints them).
  add_test(NAME kiosk_reload_soak
           COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/kiosk_reload_soak.sh
                   $<TARGET_FILE:hfshade-kiosk> $<TARGET_FILE:hfgen> 100)
  set_tests_properties(kiosk_reload_soak PROPERTIES LABELS gl TIMEOUT 300 SKIP_RETURN_CODE 77)
  if(HFS_SANITIZE)
    # quarantine_size_mb=0: ASan otherwise keeps freed memory for reuse
    # checks, and the RSS of 100 reloads grows by its quarantine (82 MB
    # measured), not by a leak; leaks are LSan's to find at exit.
    set_property(TEST kiosk_reload_soak APPEND PROPERTY ENVIRONMENT
                 "LSAN_OPTIONS=suppressions=${CMAKE_CURRENT_LIST_DIR}/lsan.supp:print_suppressions=0"
                 "ASAN_OPTIONS=quarantine_size_mb=0")
  endif()
endif()

# Issue 14: the kiosk's headless frame and `hfshade render -o` are the same
# picture, row j = 0 at the top (tests/orientation.sh).
if(TARGET hfshade-kiosk)
  add_executable(png_same_picture ${CMAKE_CURRENT_LIST_DIR}/png_same_picture.c)
  target_link_libraries(png_same_picture PRIVATE PkgConfig::HFS_PNG)
  add_test(NAME orientation
           COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/orientation.sh
                   $<TARGET_FILE:hfshade> $<TARGET_FILE:hfgen> $<TARGET_FILE:hfshade-kiosk>
                   $<TARGET_FILE:png_same_picture>)
  set_tests_properties(orientation PROPERTIES LABELS io TIMEOUT 120)
endif()

# The kiosk's map (issue 40 item 4; board/kiosk_map.h): levels, tiles lit
# through halos against one render of the whole field, tiles fetched ahead
# of a pan and a zoom, the budget, a relit map (CPU reference: "io").
if(TARGET hfs_kiosk_map)
  hfs_add_test(test_kiosk_map SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_kiosk_map.c
               LIBS hfs_kiosk_map hfs_terrain_gen m LABEL io TIMEOUT 600)
  target_include_directories(test_kiosk_map PRIVATE ${PROJECT_SOURCE_DIR}/runtime/renderer)
endif()
# The map through the program: levels, pan and zoom from replayed knobs,
# tiles fetched while idle, the budget, no map for a field that fits.
if(TARGET hfshade-kiosk)
  add_test(NAME kiosk_map COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/kiosk_map.sh
                                  $<TARGET_FILE:hfshade-kiosk> $<TARGET_FILE:hfgen>)
  set_tests_properties(kiosk_map PROPERTIES LABELS io TIMEOUT 300)
endif()
