# SH module unit tests (runtime/sh/): each compares the library with
# brute-force quadrature written independently in tests/test_sh_util.h.
foreach(t basis rotate project product zonal legendre wedge wedge_table)
  hfs_add_test(test_sh_${t}
    SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/test_sh_${t}.c
    LIBS hfs_sh m
    LABEL unit
    TIMEOUT 60)
endforeach()

# The generated GLSL product (runtime/sh/CMakeLists.txt) compiles as GLSL ES 3.00;
# needs only the validator, no GPU.  The shader exists once hfs_sh is built,
# which every test above depends on.
find_program(HFS_GLSLANG_VALIDATOR glslangValidator)
if(HFS_GLSLANG_VALIDATOR)
  add_test(NAME test_sh_glsl_product
           COMMAND ${HFS_GLSLANG_VALIDATOR} ${HFS_SH_GLSL_CHECK})
  set_tests_properties(test_sh_glsl_product PROPERTIES LABELS unit)
endif()

# Exact per-slice lighting (runtime/core/slice_light.c, issue 15): closed forms
# against quadrature, the slice table against the SH basis, flat/shadowed/
# tilted receivers against their closed forms.
hfs_add_test(test_slice_light
  SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/test_slice_light.c
  LIBS hfs_core m
  LABEL unit
  TIMEOUT 60)
