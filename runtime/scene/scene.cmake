# Scene description (INI via libinih) — a module around the core.
pkg_check_modules(INIH REQUIRED IMPORTED_TARGET inih)
add_library(hfshade_scene STATIC
  ${CMAKE_CURRENT_SOURCE_DIR}/scene/scene.c
  ${CMAKE_CURRENT_SOURCE_DIR}/scene/scene_ini.c)
target_include_directories(hfshade_scene PUBLIC ${CMAKE_CURRENT_SOURCE_DIR}/scene)
target_link_libraries(hfshade_scene PUBLIC hfs_base PRIVATE PkgConfig::INIH)
