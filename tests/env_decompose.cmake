# Environment map decomposition (runtime/envmap/, issue 17): synthetic
# skies with known disks (tools/sky_gen.c), energy conservation, seams,
# poles, degenerate and bad maps, determinism, tracking.
hfs_add_test(test_env_decompose
  SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/test_env_decompose.c
  LIBS hfs_envmap hfs_sky_gen m
  LABEL unit
  TIMEOUT 120)
# The scene key env-lights through the scene loader, and the environment
# knob turning the lights with the residual.
hfs_add_test(test_env_lights
  SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/test_env_lights.c
  LIBS hfshade_scene hfs_sky_gen m
  LABEL unit
  TIMEOUT 60)
# hfshade envmap decompose and hfgen sky end to end.
add_test(NAME envmap_cli
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/envmap_cli.sh
                 $<TARGET_FILE:hfshade> $<TARGET_FILE:hfgen>)
set_tests_properties(envmap_cli PROPERTIES LABELS io TIMEOUT 120)
