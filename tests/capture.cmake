# capture.cmake — camera inputs (docs/CAPTURE.md) without a camera:
#   test_capture         the V4L2 source against the fake device
#                        (capture_fake.c: buffer ownership, queue order,
#                        EAGAIN, a skipped sequence number, a short frame,
#                        ENODEV mid-stream and the back-off, EIO mid-stream
#                        and a sequence restarted by the reopen (no drops
#                        counted for it), a driver that
#                        changes the size), hfs-capture-info's listing,
#                        recordings and their replay ("unit")
#   test_depth_heights   plane fit, resampling, holes, the temporal filter
#                        on the synthetic sandbox: noise before/after, lag
#                        ("unit")
#   test_capture_real    a real /dev/video* device: listed and, where it
#                        offers Z16, streamed; 77 where none exists
#   kiosk_capture        hfshade-kiosk replaying a synthetic recording:
#                        frames shown, capture stats, a broken frame file
#                        mid-stream survived ("gl": 77 without GLES)

hfs_add_test(test_capture
  SOURCES test_capture.c capture_fake.c
  LIBS hfs_capture m LABEL unit TIMEOUT 60)
hfs_add_test(test_depth_heights
  SOURCES test_depth_heights.c
  LIBS hfs_capture m LABEL unit TIMEOUT 120)
hfs_add_test(test_capture_real
  SOURCES test_capture_real.c
  LIBS hfs_capture LABEL unit TIMEOUT 60)
if(TARGET hfshade-kiosk)
  add_test(NAME kiosk_capture
           COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/kiosk_capture.sh
                   $<TARGET_FILE:hfshade-kiosk> $<TARGET_FILE:hfs-capture-synth>
                   $<TARGET_FILE:hfgen>)
  set_tests_properties(kiosk_capture PROPERTIES LABELS gl TIMEOUT 300 SKIP_RETURN_CODE 77)
endif()
if(HFS_SANITIZE AND TARGET hfshade-kiosk)
  # As the kiosk's GL tests: Mesa/LLVM leaks only are suppressed.
  set_property(TEST kiosk_capture APPEND PROPERTY ENVIRONMENT
               "LSAN_OPTIONS=suppressions=${CMAKE_CURRENT_LIST_DIR}/lsan.supp:print_suppressions=0")
endif()

# A camera unplugged under a running kiosk: the fake device behind the C
# library's calls (LD_PRELOAD shim), ENODEV mid-stream, back 400 ms later.
#   kiosk_capture_loss   one warning, one "back", frames before and after,
#                        exit 0 on SIGTERM; for a heights camera, then for a
#                        sky camera ("gl": 77 without GLES)
add_library(hfs_capture_preload MODULE capture_preload.c capture_fake.c)
target_include_directories(hfs_capture_preload PRIVATE ${PROJECT_SOURCE_DIR}/board
                           ${PROJECT_SOURCE_DIR}/runtime
                           ${PROJECT_BINARY_DIR}/generated/include)
target_link_libraries(hfs_capture_preload PRIVATE ${CMAKE_DL_LIBS} Threads::Threads)
# The interposed calls must be exported (the project hides symbols by default).
set_target_properties(hfs_capture_preload PROPERTIES C_VISIBILITY_PRESET default)
if(TARGET hfshade-kiosk)
  add_test(NAME kiosk_capture_loss
           COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/kiosk_capture_loss.sh
                   $<TARGET_FILE:hfshade-kiosk> $<TARGET_FILE:hfs_capture_preload>
                   $<TARGET_FILE:hfgen>)
  set_tests_properties(kiosk_capture_loss PROPERTIES LABELS gl TIMEOUT 300 SKIP_RETURN_CODE 77)
  if(HFS_SANITIZE)
    set_property(TEST kiosk_capture_loss APPEND PROPERTY ENVIRONMENT
                 "LSAN_OPTIONS=suppressions=${CMAKE_CURRENT_LIST_DIR}/lsan.supp:print_suppressions=0")
  endif()
endif()

# The environment role (docs/CAPTURE.md "Camera to environment"):
#   test_camera_env      decoding, SPEC's conventions of each mapping, round
#                        trips of a known sky through each mapping, the
#                        fill, the moving sun tracked, the smoothing, the
#                        live path on the fake device with a loss ("unit")
hfs_add_test(test_camera_env
  SOURCES test_camera_env.c capture_fake.c
  LIBS hfs_capture m LABEL unit TIMEOUT 120)
#   test_camera_env_gl   a sky frame on the kept GLES renderer reruns the
#                        lighting's passes only (the frame report) ("gl": 77
#                        without GLES)
if(TARGET hfshade_lib)
  add_executable(test_camera_env_gl test_camera_env_gl.c)
  target_link_libraries(test_camera_env_gl PRIVATE hfs_capture hfshade_lib m)
  add_test(NAME test_camera_env_gl COMMAND test_camera_env_gl)
  set_tests_properties(test_camera_env_gl PROPERTIES SKIP_RETURN_CODE 77 LABELS gl TIMEOUT 120)
endif()
#   kiosk_capture_env    hfshade-kiosk replaying a sky camera (a moving sun):
#                        its key light follows the sun, frames differ, no
#                        terrain pass reruns; both roles at once; a bad sky
#                        section ("gl": 77 without GLES)
if(TARGET hfshade-kiosk)
  add_test(NAME kiosk_capture_env
           COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/kiosk_capture_env.sh
                   $<TARGET_FILE:hfshade-kiosk> $<TARGET_FILE:hfs-capture-synth>
                   $<TARGET_FILE:hfgen>)
  set_tests_properties(kiosk_capture_env PROPERTIES LABELS gl TIMEOUT 300 SKIP_RETURN_CODE 77)
  if(HFS_SANITIZE)
    set_property(TEST kiosk_capture_env APPEND PROPERTY ENVIRONMENT
                 "LSAN_OPTIONS=suppressions=${CMAKE_CURRENT_LIST_DIR}/lsan.supp:print_suppressions=0")
  endif()
endif()
