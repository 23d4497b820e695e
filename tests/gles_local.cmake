# gles_local.cmake — local spherical lights on the GLES path (issue 4;
# DESIGN.md "Local lights", "GLES path"), tests/test_gles_local.c, label "gl".
#   equal_SCENE_N[_full]  GLES vs CPU, local lights only, 128x128 cones /
#                         panel, N of tools/bench_local.sh's lights, fp16,
#                         Legendre, subsample 1 (full: q.local_full_swath)
#   dem, mixed, flat, sub, errors  (see test_gles_local.c)
#   *_es30 / *_sse41      the CI environments, as tests/gles.cmake
# A context that cannot be made exits 77 (skipped).
#
# Bounds (SPEC metrics, |gles - cpu| / max unshadowed): about 10x what
# llvmpipe measures per test (Mesa 22.3.6, RelWithDebInfo; Release, Debug +
# ASan/UBSan, MESA_GLES_VERSION_OVERRIDE=3.0 and GALLIUM_OVERRIDE_CPU_CAPS=
# sse4.1 give the same 3 digits).  fp16 and fp32 alike: the float arithmetic
# of the shader, not the storage, dominates.  The task's 1e-3 / 1e-2 is the
# product requirement, far above.  Since session 41 each sample also
# searches its own ray through every crossing and cell (issue 36 item 1:
# local_visibility.frag ray_horizon, cpu_local.c), which decides grazing
# rays exactly, where the shader's float and the CPU's double part: the
# partial-swath means rose from 3e-9..5e-8 to 2e-8..5.5e-7 (the truth's
# error fell 20-50x: BENCHMARKS.md "Local lights through every cell").
#                                    bound (mean max)   measured mean / max
set(hfs_loc_cones_1                  8.2e-7 3.5e-5)   # 8.13e-8 / 3.41e-6
set(hfs_loc_cones_8                  5.5e-6 5.7e-5)   # 5.50e-7 / 5.69e-6
set(hfs_loc_panel_1                  2.3e-7 1.6e-5)   # 2.30e-8 / 1.55e-6
set(hfs_loc_panel_8                  3.7e-7 2.8e-5)   # 3.70e-8 / 2.78e-6
set(hfs_loc_cones_3_full             1.9e-7 4.1e-6)   # 1.92e-8 / 4.08e-7
set(hfs_loc_cones_3_wedge            3.1e-5 4.1e-4)   # 3.09e-6 / 4.11e-5
set(hfs_loc_panel_3_fp32             6.4e-7 1.2e-4)   # 6.41e-8 / 1.14e-5
# Subsample 2: the CPU computes the same visibility grid (issue 36 item 5,
# runtime/cpu/cpu_local_grid.c), so ~10x the measurement as above (before,
# against the full-resolution CPU, the interpolation error: cones 1.454e-4
# / 1.770e-2, panel 2.573e-4 / 1.545e-2); the grid texels' bit-equality
# with subsample 1 is mode sub.
set(hfs_loc_cones_8_sub2             5.5e-6 9.8e-5)   # 5.45e-7 / 9.76e-6
set(hfs_loc_panel_8_sub2             3.6e-7 7.6e-6)   # 3.53e-8 / 7.57e-7
add_executable(test_gles_local ${CMAKE_CURRENT_LIST_DIR}/test_gles_local.c)
target_link_libraries(test_gles_local PRIVATE hfs_test_gles_scenes)
target_compile_definitions(test_gles_local PRIVATE HFS_DATA_DIR="${PROJECT_SOURCE_DIR}/data")

set(hfs_gles_local_tests "")
function(hfs_gles_local_test name)
  add_test(NAME ${name} COMMAND test_gles_local ${ARGN})
  set_tests_properties(${name} PROPERTIES SKIP_RETURN_CODE 77 LABELS gl TIMEOUT 600)
  set(hfs_gles_local_tests ${hfs_gles_local_tests} ${name} PARENT_SCOPE)
endfunction()

foreach(variant "" es30 sse41)
  set(sfx "")
  set(env "")
  if(variant STREQUAL "es30")
    set(sfx _es30)
    set(env MESA_GLES_VERSION_OVERRIDE=3.0)
  elseif(variant STREQUAL "sse41")
    set(sfx _sse41)
    set(env GALLIUM_OVERRIDE_CPU_CAPS=sse4.1)
  endif()
  set(names "")
  foreach(scene cones panel)
    foreach(n 1 8)
      hfs_gles_local_test(test_gles_local_equal_${scene}_${n}${sfx}
                          equal ${scene} ${n} partial 1 fp16 ${hfs_loc_${scene}_${n}})
      list(APPEND names test_gles_local_equal_${scene}_${n}${sfx})
    endforeach()
  endforeach()
  hfs_gles_local_test(test_gles_local_equal_cones_3_full${sfx}
                      equal cones 3 full 1 fp16 ${hfs_loc_cones_3_full})
  list(APPEND names test_gles_local_equal_cones_3_full${sfx})
  # The wedge-table path (fp16 tables).
  hfs_gles_local_test(test_gles_local_equal_cones_3_wedge${sfx}
                      equal cones 3 partial 1 fp16 ${hfs_loc_cones_3_wedge} wedge)
  list(APPEND names test_gles_local_equal_cones_3_wedge${sfx})
  foreach(scene cones panel)
    hfs_gles_local_test(test_gles_local_equal_${scene}_8_sub2${sfx}
                        equal ${scene} 8 partial 2 fp16 ${hfs_loc_${scene}_8_sub2})
    list(APPEND names test_gles_local_equal_${scene}_8_sub2${sfx})
  endforeach()
  foreach(mode dem mixed flat sub errors)
    hfs_gles_local_test(test_gles_local_${mode}${sfx} ${mode})
    list(APPEND names test_gles_local_${mode}${sfx})
  endforeach()
  if(env)
    set_tests_properties(${names} PROPERTIES ENVIRONMENT ${env})
  endif()
endforeach()
hfs_gles_local_test(test_gles_local_equal_panel_3_fp32
                    equal panel 3 partial 1 fp32 ${hfs_loc_panel_3_fp32})

if(HFS_SANITIZE)
  foreach(t IN LISTS hfs_gles_local_tests)
    set_property(TEST ${t} APPEND PROPERTY ENVIRONMENT
                 "LSAN_OPTIONS=suppressions=${CMAKE_CURRENT_LIST_DIR}/lsan.supp:print_suppressions=0")
  endforeach()
endif()
