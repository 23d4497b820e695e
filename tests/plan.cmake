# plan.cmake — the frame planner (issue 6): its decisions on a small graph.
hfs_add_test(test_frame_plan SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_frame_plan.c
             LIBS hfs_core LABEL unit)
# Planned frames equal from-scratch frames after random edits (GLES; 77
# without a context): 2000 edits on a 24x24 field; the sanitizer build,
# whose job is memory and UB errors and which runs ~8x slower, 400.
set(hfs_plan_edits 2000)
if(HFS_SANITIZE)
  set(hfs_plan_edits 400)
endif()
hfs_add_test(test_plan_equal SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_plan_equal.c
             LIBS hfshade_lib hfs_terrain_gen m LABEL gl TIMEOUT 900
             ARGS ${hfs_plan_edits} 1 24)
# The cases issue 6 names, through the public frame report (GLES).
hfs_add_test(test_plan_cases SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_plan_cases.c
             LIBS hfshade_lib hfs_terrain_gen m LABEL gl TIMEOUT 300)
# The planner's savings on realistic sequences (a benchmark, not a test):
# build/tests/bench_plan [--frames N] [--size N] (BENCHMARKS.md).
add_executable(bench_plan ${CMAKE_CURRENT_LIST_DIR}/bench_plan.c)
target_link_libraries(bench_plan PRIVATE hfshade_lib hfshade_io hfs_terrain_gen m)
target_include_directories(bench_plan PRIVATE ${PROJECT_SOURCE_DIR}/tools)
# Amortization (NS09 section 7): bounded latency, convergence to the
# from-scratch frame (GLES).
hfs_add_test(test_plan_amortize SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_plan_amortize.c
             LIBS hfshade_lib hfs_terrain_gen m LABEL gl TIMEOUT 600)
# The GLES plan's input diff without a context: each signature field alone
# runs exactly the passes that read it (the swath's sample count included).
hfs_add_test(test_gles_plan_diff SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_gles_plan_diff.c
             LIBS hfs_gles LABEL unit)
# Every scene key through the planner (issue 35, test_plan_keys.c): the
# table of scene keys walked, each key changed on a kept renderer against
# a fresh one, bit for bit (image, 3-D view, lit texture, point queries);
# on GLES ("gl", 77 without a context) and on the CPU reference ("unit").
add_executable(test_plan_keys ${CMAKE_CURRENT_LIST_DIR}/test_plan_keys.c)
target_link_libraries(test_plan_keys PRIVATE hfshade_scene hfshade_io hfshade_lib hfs_gl
                      hfs_terrain_gen hfs_sky_gen PkgConfig::HFS_EGL m)
# The sanitizer build, whose job is memory and UB errors and where the
# walk takes ~6x longer (90 s for both), walks every 5th row; the table
# is checked whole in every build.
set(hfs_plan_keys_rows "")
if(HFS_SANITIZE)
  set(hfs_plan_keys_rows every 5)
endif()
add_test(NAME test_plan_keys_gles COMMAND test_plan_keys gles ${hfs_plan_keys_rows})
set_tests_properties(test_plan_keys_gles PROPERTIES SKIP_RETURN_CODE 77 LABELS gl TIMEOUT 300)
add_test(NAME test_plan_keys_cpu COMMAND test_plan_keys cpu ${hfs_plan_keys_rows})
set_tests_properties(test_plan_keys_cpu PROPERTIES LABELS unit TIMEOUT 300)
if(HFS_SANITIZE)
  set_property(TEST test_plan_keys_gles APPEND PROPERTY ENVIRONMENT
               "LSAN_OPTIONS=suppressions=${CMAKE_CURRENT_LIST_DIR}/lsan.supp:print_suppressions=0")
endif()
# Local edits (issue 38): after random edits of the heights a kept
# renderer, which recomputes only what an edit can reach
# (runtime/gles/edit_frame.h), equals one that recomputes everything, bit
# for bit, in twelve scenes; and takes the edit path whenever the range holds.
# Also under the ES 3.0 minimums (HFS_GL_STRICT_LIMITS=1: smaller draws,
# blocks from textures) on an ES 3.0 context.
set(hfs_edit_count 40)
if(HFS_SANITIZE)
  set(hfs_edit_count 8)
endif()
hfs_add_test(test_gles_edits SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_gles_edits.c
             LIBS hfshade_lib hfs_terrain_gen m LABEL gl TIMEOUT 900
             ARGS ${hfs_edit_count} 1 72 56)
add_test(NAME test_gles_edits_strict COMMAND test_gles_edits ${hfs_edit_count} 2 61 47)
set_tests_properties(test_gles_edits_strict PROPERTIES SKIP_RETURN_CODE 77 LABELS gl TIMEOUT 900
                     ENVIRONMENT "HFS_GL_STRICT_LIMITS=1;MESA_GLES_VERSION_OVERRIDE=3.0")
if(HFS_SANITIZE)
  set_property(TEST test_gles_edits test_gles_edits_strict APPEND PROPERTY ENVIRONMENT
               "LSAN_OPTIONS=suppressions=${CMAKE_CURRENT_LIST_DIR}/lsan.supp:print_suppressions=0")
endif()
# What a local edit costs (a benchmark, not a test): build/tests/bench_edits
# [--size N] [--rounds R] (BENCHMARKS.md "Local edits").
add_executable(bench_edits ${CMAKE_CURRENT_LIST_DIR}/bench_edits.c)
target_link_libraries(bench_edits PRIVATE hfshade_lib hfs_terrain_gen m)
target_include_directories(bench_edits PRIVATE ${PROJECT_SOURCE_DIR}/tools)
# The regions local edits recompute, against brute force (no driver).
hfs_add_test(test_edit_region SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_edit_region.c
             LIBS hfs_gles m LABEL unit)
# The SH sky's occluded light as one target until the sky turns, then the
# transfer (pass_env_sky_occlusion.c): the passes, the memory, and the two
# renderers' images bit for bit (GLES).
hfs_add_test(test_gles_sky_occlusion SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_gles_sky_occlusion.c
             LIBS hfshade_lib hfs_terrain_gen m LABEL gl TIMEOUT 300)
