# gl.cmake — headless GL tests (label "gl"): contexts, function table,
# embedded shaders, RGBA16F render + readback against the C twin of the
# pattern.  A context that cannot be made here exits 77 (skipped, with the
# reason).  Variants re-run the render tests under Mesa's environment knobs:
#   *_es30   MESA_GLES_VERSION_OVERRIDE=3.0  (an ES 3.0 context, as on boards)
#   *_sse41  GALLIUM_OVERRIDE_CPU_CAPS=sse4.1 (llvmpipe without AVX)
#   test_gl_context_auto_fallback: libglvnd offered no EGL vendor, so "auto"
#            must pick osmesa (skipped where the variable has no effect).
# They are ignored by non-Mesa drivers.
#
# Sanitizer builds (HFS_SANITIZE) run with tests/lsan.supp, which suppresses
# leaks inside Mesa/LLVM only.

add_library(hfs_test_gl_pattern STATIC ${CMAKE_CURRENT_LIST_DIR}/gl_pattern.c)
target_include_directories(hfs_test_gl_pattern PUBLIC ${CMAKE_CURRENT_LIST_DIR})
target_link_libraries(hfs_test_gl_pattern PUBLIC hfs_gl m)

hfs_add_test(test_gl_names LABEL gl SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_gl_names.c
             LIBS hfs_gl)
hfs_add_test(test_gl_half LABEL gl SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_gl_half.c
             LIBS hfs_gl m)
# One executable per program, one test per (backend, environment).
foreach(exe test_gl_context test_gl_multi)
  add_executable(${exe} ${CMAKE_CURRENT_LIST_DIR}/${exe}.c)
  target_link_libraries(${exe} PRIVATE hfs_gl hfs_test_gl_pattern)
endforeach()

set(hfs_gl_tests test_gl_names test_gl_half)
function(hfs_gl_test name exe)
  add_test(NAME ${name} COMMAND ${exe} ${ARGN})
  set_tests_properties(${name} PROPERTIES SKIP_RETURN_CODE 77 LABELS gl TIMEOUT 120)
  set(hfs_gl_tests ${hfs_gl_tests} ${name} PARENT_SCOPE)
endfunction()
hfs_gl_test(test_gl_context_surfaceless test_gl_context surfaceless)
hfs_gl_test(test_gl_context_auto test_gl_context auto)
hfs_gl_test(test_gl_multi_surfaceless test_gl_multi surfaceless surfaceless)
hfs_gl_test(test_gl_context_surfaceless_es30 test_gl_context surfaceless)
hfs_gl_test(test_gl_context_surfaceless_sse41 test_gl_context surfaceless)
set_tests_properties(test_gl_context_surfaceless_es30 PROPERTIES
                     ENVIRONMENT MESA_GLES_VERSION_OVERRIDE=3.0)
set_tests_properties(test_gl_context_surfaceless_sse41
                     PROPERTIES ENVIRONMENT GALLIUM_OVERRIDE_CPU_CAPS=sse4.1)
# The osmesa context's tests exist where it is built (a test that skips
# because its backend was configured out would hide a broken build).
if(HFS_HAVE_OSMESA)
  hfs_gl_test(test_gl_context_osmesa test_gl_context osmesa)
  hfs_gl_test(test_gl_context_auto_fallback test_gl_context auto osmesa)
  hfs_gl_test(test_gl_multi_osmesa test_gl_multi surfaceless osmesa)
  hfs_gl_test(test_gl_context_osmesa_sse41 test_gl_context osmesa)
  # libglvnd with no vendor: surfaceless is not offered, auto must fall back.
  set_tests_properties(test_gl_context_auto_fallback PROPERTIES
                       ENVIRONMENT __EGL_VENDOR_LIBRARY_FILENAMES=/nonexistent/hfs_no_vendor.json)
  set_tests_properties(test_gl_context_osmesa_sse41
                       PROPERTIES ENVIRONMENT GALLIUM_OVERRIDE_CPU_CAPS=sse4.1)
endif()

if(HFS_SANITIZE)
  foreach(t IN LISTS hfs_gl_tests)
    set_property(TEST ${t} APPEND PROPERTY ENVIRONMENT
                 "LSAN_OPTIONS=suppressions=${CMAKE_CURRENT_LIST_DIR}/lsan.supp:print_suppressions=0")
  endforeach()
endif()
