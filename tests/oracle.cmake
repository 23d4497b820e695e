# oracle.cmake — oracles that do NOT use the shared setup code they check
# (the GLES-vs-CPU tests take swaths, folded matrices, rotations and tables
# from the same CPU functions as the reference, so a bug there checks
# itself).  Each test writes its definition out independently; see the
# header of each source for what it checks and how its bounds were measured.
#
#   test_swath_oracle        hfs_swath_key / hfs_swath_full and the GLES swath
#                            and key blocks (runtime/gles/uniform_blocks.c) against the closed
#                            form of DESIGN.md "Azimuth swaths" ("unit")
#   test_swath_oracle_{nk1,tiny_alpha,black_sun}
#                            the defects it found, one mode each (see
#                            test_swath_oracle.c): nphi_key = 1 spacing,
#                            tiny alpha off the lattice, a sun below
#                            ulp(elev)/2 black on the CPU backend.
hfs_add_test(test_swath_oracle LABEL unit TIMEOUT 120
             SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_swath_oracle.c LIBS hfshade_lib hfs_gles m)
foreach(issue nk1 tiny-alpha black-sun)
  string(REPLACE "-" "_" t ${issue})
  add_test(NAME test_swath_oracle_${t} COMMAND test_swath_oracle ${issue})
  set_tests_properties(test_swath_oracle_${t} PROPERTIES LABELS unit TIMEOUT 60)
endforeach()
#   test_sh_oracle           SH basis, z-rotation, clamped cosine and the
#                            renderer's env_rotate against SPEC's table written
#                            out in the test ("unit")
hfs_add_test(test_sh_oracle LABEL unit TIMEOUT 120
             SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_sh_oracle.c LIBS hfshade_lib m)
#   test_sh_glsl_gpu         the generated GLSL SH product as the renderer
#                            embeds it, run on the driver against
#                            hfs_sh_product (random pairs, every basis pair),
#                            and the GLES backend's env_rotate ("gl"; 77 only
#                            when no context can be made)
hfs_add_test(test_sh_glsl_gpu LABEL gl TIMEOUT 300
             SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_sh_glsl_gpu.c LIBS hfshade_lib hfs_gles m)
#   test_glsl_numerics_gpu   the shader library's numerics run on the driver
#                            (tests/gl_bits.h): the small-angle sine and the
#                            caps against lights.c in double, the halves bit
#                            for bit, the filter probe against its own sweep,
#                            the shaders' blend of pairs against a double
#                            bilinear ("gl"; 77 only when no context can be
#                            made)
hfs_add_test(test_glsl_numerics_gpu LABEL gl TIMEOUT 60
             SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_glsl_numerics_gpu.c LIBS hfshade_lib hfs_gles m)
if(HFS_SANITIZE)
  set_property(TEST test_sh_glsl_gpu test_glsl_numerics_gpu APPEND PROPERTY ENVIRONMENT
               "LSAN_OPTIONS=suppressions=${CMAKE_CURRENT_LIST_DIR}/lsan.supp:print_suppressions=0")
endif()
