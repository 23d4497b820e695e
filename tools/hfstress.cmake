# hfstress — numerical stability under extremes (issue 5, docs/STRESS.md):
# a table of extreme cases run on every backend with bound, invariance and
# fp16-vs-fp32 checks.  `hfstress` runs all of it; `hfstress --fast` is the
# CI subset, registered here as the ctest label "stress":
#   stress_fast_cpu   CPU reference and ground truth (always runs)
#   stress_fast_gles  GLES fp16 and fp32 (exit 77 = skipped without a context)
#   stress_fast_slice every case on the exact slice path (issue 15), CPU and
#                     GLES (exit 77 = skipped without a context)
#   stress_fast_pair_fetch  GLES with HFS_GL_PAIR_FETCH=1 (runtime/gl/gl_probe.h)
add_executable(hfstress
  ${CMAKE_CURRENT_SOURCE_DIR}/hfstress.c
  ${CMAKE_CURRENT_SOURCE_DIR}/hfstress_backends.c
  ${CMAKE_CURRENT_SOURCE_DIR}/hfstress_cases.c
  ${CMAKE_CURRENT_SOURCE_DIR}/hfstress_checks.c)
target_link_libraries(hfstress PRIVATE hfshade_lib hfshade_io hfs_terrain_gen hfs_sh hfs_cli_usage m)

add_test(NAME stress_fast_cpu COMMAND hfstress --fast --backend cpu,truth)
add_test(NAME stress_fast_gles COMMAND hfstress --fast --backend gles)
add_test(NAME stress_fast_slice COMMAND hfstress --fast --visibility slice --backend cpu,gles)
# heights and ratios blended by the shaders, as on a driver whose LINEAR is
# inexact (runtime/gl/gl_probe.h: NVIDIA's); llvmpipe's is not, so it is forced
add_test(NAME stress_fast_pair_fetch COMMAND hfstress --fast --backend gles)
set_tests_properties(stress_fast_cpu stress_fast_gles stress_fast_slice stress_fast_pair_fetch
                     PROPERTIES LABELS stress TIMEOUT 600 SKIP_RETURN_CODE 77)
set_property(TEST stress_fast_pair_fetch APPEND PROPERTY ENVIRONMENT HFS_GL_PAIR_FETCH=1)
# the longest tests start first (tests/CMakeLists.txt "COST")
set_tests_properties(stress_fast_gles PROPERTIES COST 90)
set_tests_properties(stress_fast_slice PROPERTIES COST 23)
set_tests_properties(stress_fast_pair_fetch PROPERTIES COST 102)
if(HFS_SANITIZE)
  # Mesa/LLVM allocations LSan reports at exit (tests/lsan.supp, as tests/gles.cmake).
  set_property(TEST stress_fast_gles stress_fast_slice stress_fast_pair_fetch APPEND PROPERTY ENVIRONMENT
               "LSAN_OPTIONS=suppressions=${PROJECT_SOURCE_DIR}/tests/lsan.supp:print_suppressions=0")
endif()
