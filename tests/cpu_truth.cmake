# The CPU reference against the brute-force ground truth (test_cpu_truth.c):
# the environment (plain and rotated), four key lights and a local light, each
# on cones, fractal terrain, a window of the DEM and a cliff (40x40), SPEC
# metrics with bounds at 1.2x the measured error.  One test per lighting and
# scene, test_cpu_truth_LIGHTING_SCENE, so a failure names both.  Label
# "unit": pure CPU, no device.
if(TARGET hfshade_io)
  add_executable(test_cpu_truth ${CMAKE_CURRENT_LIST_DIR}/test_cpu_truth.c)
  target_link_libraries(test_cpu_truth PRIVATE hfshade_lib hfshade_io hfs_terrain_gen m)
  target_compile_definitions(test_cpu_truth PRIVATE HFS_DATA_DIR="${PROJECT_SOURCE_DIR}/data")
  foreach(lighting env env_rotated key_a key_b key_c key_d local)
    foreach(scene cones fractal dem cliff)
      add_test(NAME test_cpu_truth_${lighting}_${scene}
               COMMAND test_cpu_truth ${lighting} ${scene})
      set_tests_properties(test_cpu_truth_${lighting}_${scene} PROPERTIES
                           LABELS unit TIMEOUT 120)
    endforeach()
  endforeach()
endif()
