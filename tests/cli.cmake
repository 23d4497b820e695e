# The command-line tool end to end: broken inputs and a good render; and
# every program's bad command lines, one line each (issue 34).
add_test(NAME cli_bad_inputs
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli_bad_inputs.sh
                 $<TARGET_FILE:hfshade> $<TARGET_FILE:hfgen>
                 ${CMAKE_CURRENT_SOURCE_DIR}/data/broken
                 # every other program, for its bad command lines (issue 34)
                 hfstress=$<TARGET_FILE:hfstress> hfbench=$<TARGET_FILE:hfbench>
                 bench_env=$<TARGET_FILE:bench_env> gles_bench=$<TARGET_FILE:gles_bench>
                 hfshade-kiosk=$<TARGET_FILE:hfshade-kiosk>
                 hfs-capture-info=$<TARGET_FILE:hfs-capture-info>
                 hfs-capture-synth=$<TARGET_FILE:hfs-capture-synth>)
set_tests_properties(cli_bad_inputs PROPERTIES LABELS io TIMEOUT 300)


# The hostile-user corpus (issue 13, tests/hostile.sh): a few hundred
# generated bad inputs through hfshade and the kiosk: exit status, one-line
# message naming the input, files left exactly as found, no hang, finite
# outputs.  Counts per class: docs/STRESS.md.
if(TARGET hfshade-kiosk)
add_executable(hostile_pfm_check ${CMAKE_CURRENT_SOURCE_DIR}/hostile_pfm_check.c)
target_link_libraries(hostile_pfm_check PRIVATE hfshade_io m)
add_test(NAME hostile
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/hostile.sh
                 $<TARGET_FILE:hfshade> $<TARGET_FILE:hfgen> $<TARGET_FILE:hfshade-kiosk>
                 $<TARGET_FILE:hostile_pfm_check>)
set_tests_properties(hostile PROPERTIES LABELS io TIMEOUT 900)
if(HFS_SANITIZE)
  set_property(TEST hostile APPEND PROPERTY ENVIRONMENT
               "LSAN_OPTIONS=suppressions=${CMAKE_CURRENT_SOURCE_DIR}/lsan.supp:print_suppressions=0")
endif()
endif()

# hfgen albedo: the benchmarks' albedo maps (tools/bench_bounce.sh ALBEDO=map).
add_test(NAME hfgen_albedo
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/hfgen_albedo.sh
                 $<TARGET_FILE:hfgen> $<TARGET_FILE:hfshade>)
set_tests_properties(hfgen_albedo PROPERTIES LABELS io TIMEOUT 60)

# Issue 41: hue clipping.  A 3-D view whose sky is ten stops over the terrain
# keeps each sky pixel's hue in hfshade render's PNG, the terrain's median
# at middle grey (tests/test_sky_hue.c states the bounds).
hfs_add_test(test_sky_hue LABEL io TIMEOUT 120 SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/test_sky_hue.c
             LIBS hfshade_io m ARGS $<TARGET_FILE:hfshade> $<TARGET_FILE:hfgen>)
add_dependencies(test_sky_hue hfshade hfgen)
