# gles.cmake — the GLES renderer (runtime/gles_*.c).
#   test_gles_units       capability layer and CPU-side setup, no driver ("unit")
#   test_gles_*           against the CPU reference and on their own ("gl"):
#     equal_SCENE_PREC_PATH  SPEC metrics vs cpu at default settings,
#                            subsample 1 (bounds below, stated per test)
#     sub2_/sub4_SCENE       the error sub-sampling adds (fp16, Legendre)
#     determinism, cache, flat, timing, errors  (see test_gles_render.c)
#   *_es30   MESA_GLES_VERSION_OVERRIDE=3.0 (an ES 3.0 context, as on boards)
#   *_sse41  GALLIUM_OVERRIDE_CPU_CAPS=sse4.1 (llvmpipe without AVX)
# A context that cannot be made exits 77 (skipped, with the reason).
# Sanitizer builds run the gl tests with tests/lsan.supp (Mesa/LLVM leaks).
#
# Bounds (mean, max of |gles - cpu| / max unshadowed, SPEC metrics), set at
# 3-5x what llvmpipe measures (DESIGN.md "GLES path"); the issue asks for
# 2e-3 / 2e-2 at fp16:
#   subsample 1   fp16  mean 1e-4, max 1e-3     fp32  mean 3e-6, max 1.5e-4
#   subsample 2/4 (an approximation of the full-resolution reference, so a
#                 measured envelope per scene, ~1.5x the measurement)
add_library(hfs_test_gles_scenes STATIC ${CMAKE_CURRENT_LIST_DIR}/test_gles_scenes.c)
target_include_directories(hfs_test_gles_scenes PUBLIC ${CMAKE_CURRENT_LIST_DIR})
target_link_libraries(hfs_test_gles_scenes PUBLIC hfshade_lib hfshade_io hfs_terrain_gen m)

add_executable(test_gles_render ${CMAKE_CURRENT_LIST_DIR}/test_gles_render.c)
target_link_libraries(test_gles_render PRIVATE hfs_test_gles_scenes)
target_compile_definitions(test_gles_render PRIVATE HFS_DATA_DIR="${PROJECT_SOURCE_DIR}/data")

# Measurement tool (not a test): see the header of test_gles_bench.c.
add_executable(gles_bench ${CMAKE_CURRENT_LIST_DIR}/test_gles_bench.c)
target_link_libraries(gles_bench PRIVATE hfs_test_gles_scenes)
target_compile_definitions(gles_bench PRIVATE HFS_DATA_DIR="${PROJECT_SOURCE_DIR}/data")

hfs_add_test(test_gles_units LABEL unit TIMEOUT 120
             SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_gles_units.c LIBS hfs_gles m)

set(hfs_gles_tests "")
function(hfs_gles_test name)
  add_test(NAME ${name} COMMAND test_gles_render ${ARGN})
  set_tests_properties(${name} PROPERTIES SKIP_RETURN_CODE 77 LABELS gl TIMEOUT 600)
  set(hfs_gles_tests ${hfs_gles_tests} ${name} PARENT_SCOPE)
endfunction()

foreach(scene cones fractal dem)
  foreach(path legendre tables)
    hfs_gles_test(test_gles_equal_${scene}_fp16_${path} equal ${scene} fp16 ${path} 1 1e-4 1e-3)
    hfs_gles_test(test_gles_equal_${scene}_fp32_${path} equal ${scene} fp32 ${path} 1 3e-6 1.5e-4)
  endforeach()
endforeach()
# Sub-sampling: measured (mean, max) cones 1.2e-3/0.11 (2), 3.1e-3/0.16 (4);
# fractal (relief 1 at 64x64: slopes up to ~5) 3.4e-2/0.53, 6.6e-2/0.62;
# DEM 5.9e-3/0.20, 1.5e-2/0.28.
hfs_gles_test(test_gles_sub2_cones equal cones fp16 legendre 2 2e-3 0.2)
hfs_gles_test(test_gles_sub4_cones equal cones fp16 legendre 4 5e-3 0.3)
hfs_gles_test(test_gles_sub2_fractal equal fractal fp16 legendre 2 5e-2 0.8)
hfs_gles_test(test_gles_sub4_fractal equal fractal fp16 legendre 4 1e-1 0.9)
hfs_gles_test(test_gles_sub2_dem equal dem fp16 legendre 2 1e-2 0.3)
hfs_gles_test(test_gles_sub4_dem equal dem fp16 legendre 4 2.5e-2 0.4)
foreach(mode determinism cache flat timing errors variants)
  hfs_gles_test(test_gles_${mode} ${mode})
endforeach()
# The same backend on the OSMesa fallback context (skipped where not built).
hfs_gles_test(test_gles_equal_fractal_fp16_legendre_osmesa equal fractal fp16 legendre 1 1e-4 1e-3 osmesa)
hfs_gles_test(test_gles_equal_dem_fp32_tables_osmesa equal dem fp32 tables 1 3e-6 1.5e-4 osmesa)

# The CI environments: an ES 3.0 context, and llvmpipe without AVX.
foreach(variant es30 sse41)
  if(variant STREQUAL "es30")
    set(env MESA_GLES_VERSION_OVERRIDE=3.0)
  else()
    set(env GALLIUM_OVERRIDE_CPU_CAPS=sse4.1)
  endif()
  foreach(scene cones fractal dem)
    hfs_gles_test(test_gles_equal_${scene}_fp16_legendre_${variant}
                  equal ${scene} fp16 legendre 1 1e-4 1e-3)
    set_tests_properties(test_gles_equal_${scene}_fp16_legendre_${variant} PROPERTIES ENVIRONMENT ${env})
  endforeach()
  hfs_gles_test(test_gles_equal_fractal_fp32_tables_${variant} equal fractal fp32 tables 1 3e-6 1.5e-4)
  set_tests_properties(test_gles_equal_fractal_fp32_tables_${variant} PROPERTIES ENVIRONMENT ${env})
  foreach(mode determinism flat errors variants)
    hfs_gles_test(test_gles_${mode}_${variant} ${mode})
    set_tests_properties(test_gles_${mode}_${variant} PROPERTIES ENVIRONMENT ${env})
  endforeach()
endforeach()

if(HFS_SANITIZE)
  foreach(t IN LISTS hfs_gles_tests)
    set_property(TEST ${t} APPEND PROPERTY ENVIRONMENT
                 "LSAN_OPTIONS=suppressions=${CMAKE_CURRENT_LIST_DIR}/lsan.supp:print_suppressions=0")
  endforeach()
endif()
