# CPU reference renderer (runtime/cpu_*.c): pure math and logic, no GPU.
foreach(t pyramid horizon visibility render)
  hfs_add_test(test_cpu_${t} SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/test_cpu_${t}.c
               LIBS hfs_cpu m LABEL unit TIMEOUT 120)
endforeach()
