# python.cmake — the hfshade Python module (issue 40; tools/python/hfshade,
# docs/PYTHON.md), label "python": tests/python/test_*.py run with Debian's
# /usr/bin/python3 (numpy, cffi and osgeo.gdal are Debian's python3-numpy,
# python3-cffi, python3-gdal, tools/install-deps.sh), the module from the
# source tree, the libraries from the build tree (HFSHADE_LIBRARY,
# HFSHADE_GIS_LIBRARY), `hfshade` the build's.  A test exits 77 (skipped)
# with its reason when numpy or cffi is missing.
#
# Under HFS_SANITIZE the libraries are ASan+UBSan-instrumented and python
# is not: python runs with the compiler's sanitizer runtimes preloaded
# (LD_PRELOAD, found with -print-file-name) and leak detection off (the
# interpreter's own allocations at exit are not ours).
find_program(HFS_PYTHON3 NAMES python3 PATHS /usr/bin NO_DEFAULT_PATH)
if(NOT HFS_PYTHON3)
  find_program(HFS_PYTHON3 NAMES python3)
endif()

# python_layout: the headers' struct layouts, compared with the cdef.
add_executable(python_layout ${CMAKE_CURRENT_LIST_DIR}/python_layout.c)
target_link_libraries(python_layout PRIVATE hfs_public)
target_include_directories(python_layout PRIVATE ${PROJECT_SOURCE_DIR}/tools/gis)

# python_julian_day: the commands' Julian day of a date-time (the parser's),
# compared with the library's of the same instant in seconds (test_sun.py).
add_executable(python_julian_day ${CMAKE_CURRENT_LIST_DIR}/python/julian_day.c)
target_link_libraries(python_julian_day PRIVATE hfs_solar)

set(hfs_py_env
    "PYTHONPATH=${PROJECT_SOURCE_DIR}/tools/python:${CMAKE_CURRENT_LIST_DIR}/python"
    "HFSHADE_LIBRARY=$<TARGET_FILE:hfshade_shared>"
    "HFSHADE_GIS_LIBRARY=$<TARGET_FILE:hfshade_gis_shared>"
    "HFSHADE_CLI=$<TARGET_FILE:hfshade>"
    "HFSHADE_LAYOUT=$<TARGET_FILE:python_layout>"
    "HFSHADE_JULIAN_DAY=$<TARGET_FILE:python_julian_day>"
    "HFSHADE_VERSION=${PROJECT_VERSION}"
    "HFSHADE_EXAMPLE=${PROJECT_SOURCE_DIR}/tools/examples/python/svf_geotiff.py"
    "PYTHONDONTWRITEBYTECODE=1")
set(hfs_py_skip "")
if(HFS_SANITIZE)
  set(hfs_py_preload "")
  if(CMAKE_C_COMPILER_ID STREQUAL "GNU")
    set(hfs_py_runtimes libasan.so libubsan.so)
  else()
    set(hfs_py_runtimes libclang_rt.asan-x86_64.so)
  endif()
  foreach(rt IN LISTS hfs_py_runtimes)
    execute_process(COMMAND ${CMAKE_C_COMPILER} -print-file-name=${rt}
                    OUTPUT_VARIABLE rt_path OUTPUT_STRIP_TRAILING_WHITESPACE)
    if(IS_ABSOLUTE "${rt_path}" AND EXISTS "${rt_path}")
      list(APPEND hfs_py_preload ${rt_path})
    else()
      set(hfs_py_skip "the sanitizer runtime ${rt} was not found (${CMAKE_C_COMPILER} -print-file-name)")
    endif()
  endforeach()
  string(REPLACE ";" ":" hfs_py_preload "${hfs_py_preload}")
  list(APPEND hfs_py_env "LD_PRELOAD=${hfs_py_preload}"
       "ASAN_OPTIONS=detect_leaks=0:verify_asan_link_order=0"
       "UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1")
endif()

foreach(area layout render gis sun envmap errors example)
  if(NOT HFS_PYTHON3)
    add_test(NAME python_${area} COMMAND sh -c "echo 'SKIP: no python3'; exit 77")
  elseif(hfs_py_skip)
    add_test(NAME python_${area} COMMAND sh -c "echo 'SKIP: ${hfs_py_skip}'; exit 77")
  else()
    add_test(NAME python_${area}
             COMMAND ${HFS_PYTHON3} ${CMAKE_CURRENT_LIST_DIR}/python/test_${area}.py)
  endif()
  set_tests_properties(python_${area} PROPERTIES ENVIRONMENT "${hfs_py_env}"
                       SKIP_RETURN_CODE 77 LABELS "python" TIMEOUT 300)
endforeach()
# The GLES equalities make a GL context: the gl tests' label too.
set_tests_properties(python_render python_gis python_sun PROPERTIES LABELS "python;gl")
