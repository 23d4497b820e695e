# hfs_sh: order-4 SH math, NLP (Legendre) visibility, wedge matrices/tables.
# Included from runtime/CMakeLists.txt (paths relative to runtime/).
#
# The SH triple-product tensor is generated at build time by
# tools/gen_sh_tables.c (exact quadrature) into this directory's build dir:
#   sh_product_gen.inc     #included by sh_product.c (const table + unrolled code)
#   sh_product.glsl.inc    GLSL ES twin for the GLES renderer; its path is in
#                          the cache variable HFS_SH_GLSL_PRODUCT, and targets
#                          that embed it add_dependencies(<target> hfs_sh_tables).
# The generator and the command live here so that the ordering is
# self-contained (the generator links only sh.c, not the library it feeds).

add_executable(hfs_gen_sh_tables
  ${CMAKE_CURRENT_SOURCE_DIR}/../tools/gen_sh_tables.c
  ${CMAKE_CURRENT_SOURCE_DIR}/sh.c)
target_include_directories(hfs_gen_sh_tables PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
target_link_libraries(hfs_gen_sh_tables PRIVATE m)

set(HFS_SH_GEN_C ${CMAKE_CURRENT_BINARY_DIR}/sh_product_gen.inc)
set(HFS_SH_GLSL_PRODUCT ${CMAKE_CURRENT_BINARY_DIR}/sh_product.glsl.inc
    CACHE INTERNAL "Generated GLSL SH product (hfs_sh_tables)")
set(HFS_SH_GLSL_CHECK ${CMAKE_CURRENT_BINARY_DIR}/sh_product_check.frag
    CACHE INTERNAL "Fragment shader wrapping the GLSL SH product, for validation")
add_custom_command(
  OUTPUT ${HFS_SH_GEN_C} ${HFS_SH_GLSL_PRODUCT} ${HFS_SH_GLSL_CHECK}
  COMMAND hfs_gen_sh_tables ${HFS_SH_GEN_C} ${HFS_SH_GLSL_PRODUCT} ${HFS_SH_GLSL_CHECK}
  DEPENDS hfs_gen_sh_tables
  COMMENT "Generating SH triple-product tables"
  VERBATIM)
# One custom target owns the command, so parallel builds never run it twice.
add_custom_target(hfs_sh_tables
  DEPENDS ${HFS_SH_GEN_C} ${HFS_SH_GLSL_PRODUCT} ${HFS_SH_GLSL_CHECK})

add_library(hfs_sh STATIC
  ${CMAKE_CURRENT_SOURCE_DIR}/sh.c
  ${CMAKE_CURRENT_SOURCE_DIR}/sh_product.c
  ${CMAKE_CURRENT_SOURCE_DIR}/sh_legendre.c
  ${CMAKE_CURRENT_SOURCE_DIR}/sh_wedge.c
  ${CMAKE_CURRENT_SOURCE_DIR}/sh_wedge_table.c)
add_dependencies(hfs_sh hfs_sh_tables)
target_include_directories(hfs_sh PUBLIC ${CMAKE_CURRENT_SOURCE_DIR}
                           PRIVATE ${CMAKE_CURRENT_BINARY_DIR})
target_compile_definitions(hfs_sh PRIVATE HFS_BUILDING_LIBRARY)
target_link_libraries(hfs_sh PUBLIC hfs_base m)
