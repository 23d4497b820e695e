# Scene description (INI via libinih) — a module around the core.
pkg_check_modules(INIH REQUIRED IMPORTED_TARGET inih)
add_library(hfshade_scene STATIC
  ${CMAKE_CURRENT_SOURCE_DIR}/scene/scene.c
  ${CMAKE_CURRENT_SOURCE_DIR}/scene/scene_ini.c)
target_include_directories(hfshade_scene PUBLIC ${CMAKE_CURRENT_SOURCE_DIR}/scene)
target_link_libraries(hfshade_scene PUBLIC hfs_base PRIVATE PkgConfig::INIH)

# Scene to renderer inputs (heights loaded, environment map projected to SH,
# lighting and quality validated), shared by tools/hfshade and the kiosk.
# Its own library so that hfshade_scene stays a parser and libhfshade
# (hfshade_lib) gains no dependency on the file formats.
add_library(hfshade_scene_load STATIC ${CMAKE_CURRENT_SOURCE_DIR}/scene/scene_load.c)
target_include_directories(hfshade_scene_load PUBLIC ${CMAKE_CURRENT_SOURCE_DIR}/scene)
target_link_libraries(hfshade_scene_load PUBLIC hfshade_scene hfshade_io hfshade_lib hfs_sh hfs_envdec)
