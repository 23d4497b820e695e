# drift.cmake — accuracy drift (issue 35, deliverable 2; test_drift.c):
# at the default quality and each quality preset, on a fractal, a rough
# field and narrow blocks (48x40, dx != 1), the CPU reference against the
# ground truth (test_drift_truth_SCENE, "unit") and GLES against the CPU
# reference (test_drift_gles_SCENE, "gl"), mean and p99 each bounded at
# 1.2x its measurement.
add_executable(test_drift ${CMAKE_CURRENT_LIST_DIR}/test_drift.c)
target_link_libraries(test_drift PRIVATE hfshade_lib hfs_gl hfs_terrain_gen m)
foreach(scene fractal rough blocks)
  add_test(NAME test_drift_truth_${scene} COMMAND test_drift truth ${scene})
  set_tests_properties(test_drift_truth_${scene} PROPERTIES LABELS unit TIMEOUT 300)
  add_test(NAME test_drift_gles_${scene} COMMAND test_drift gles ${scene})
  set_tests_properties(test_drift_gles_${scene} PROPERTIES SKIP_RETURN_CODE 77 LABELS gl
                       TIMEOUT 300)
  # and on an ES 3.0 context, as on boards (the same numbers)
  add_test(NAME test_drift_gles_${scene}_es30 COMMAND test_drift gles ${scene})
  set_tests_properties(test_drift_gles_${scene}_es30 PROPERTIES SKIP_RETURN_CODE 77 LABELS gl
                       TIMEOUT 300 ENVIRONMENT MESA_GLES_VERSION_OVERRIDE=3.0)
  if(HFS_SANITIZE)
    foreach(t test_drift_gles_${scene} test_drift_gles_${scene}_es30)
      set_property(TEST ${t} APPEND PROPERTY ENVIRONMENT
                   "LSAN_OPTIONS=suppressions=${CMAKE_CURRENT_LIST_DIR}/lsan.supp:print_suppressions=0")
    endforeach()
  endif()
endforeach()
# The rules those numbers rest on, checked directly against closed forms
# (test_drift_rules.c): split horizons' sub-directions, near/far boundary,
# settings and refine counts (test_drift_rules_split), an environment map's
# slice wedges (test_drift_rules_map_slices).
add_executable(test_drift_rules ${CMAKE_CURRENT_LIST_DIR}/test_drift_rules.c)
target_link_libraries(test_drift_rules PRIVATE hfs_core m)
foreach(part split map_slices)
  add_test(NAME test_drift_rules_${part} COMMAND test_drift_rules ${part})
  set_tests_properties(test_drift_rules_${part} PROPERTIES LABELS unit TIMEOUT 60)
endforeach()
