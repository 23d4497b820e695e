# gl/context.cmake — hfs_glctx: the library's GL contexts (gl_context.h) and
# the skip rule of GL tests and hfstress (gl_require.h).  Part of the library:
# runtime/ includes nothing from board/ (board/ builds displays on top).
#   surfaceless  EGL (pkg-config egl), always built
#   osmesa       OSMesa (pkg-config osmesa, headers) when HFS_WITH_OSMESA is ON
#                and found, loaded at run time with dlopen (never linked);
#                otherwise the backend answers "not built".
# GL itself is not linked: the renderer loads GL entry points from the context
# (runtime/gl_api.h), because OSMesa is not behind libglvnd's libGLESv2.

pkg_check_modules(HFS_EGL REQUIRED IMPORTED_TARGET GLOBAL egl) # board/ displays use it too

add_library(hfs_glctx STATIC
  ${CMAKE_CURRENT_LIST_DIR}/gl_context.c
  ${CMAKE_CURRENT_LIST_DIR}/gl_require.c
  ${CMAKE_CURRENT_LIST_DIR}/egl_surfaceless.c
  ${CMAKE_CURRENT_LIST_DIR}/egl_shared.c
  ${CMAKE_CURRENT_LIST_DIR}/egl_util.c
  ${CMAKE_CURRENT_LIST_DIR}/osmesa.c)
target_include_directories(hfs_glctx PUBLIC ${CMAKE_CURRENT_LIST_DIR})
target_compile_definitions(hfs_glctx PRIVATE HFS_BUILDING_LIBRARY)
target_link_libraries(hfs_glctx PUBLIC hfs_base PRIVATE PkgConfig::HFS_EGL)

set(HFS_HAVE_OSMESA OFF)
if(HFS_WITH_OSMESA)
  pkg_check_modules(HFS_OSMESA IMPORTED_TARGET osmesa)
  if(HFS_OSMESA_FOUND)
    set(HFS_HAVE_OSMESA ON)
    target_compile_definitions(hfs_glctx PRIVATE HFS_HAVE_OSMESA=1)
    # Headers only: libOSMesa is dlopen'ed by osmesa.c, so neither
    # libhfshade nor the tools link it.
    target_include_directories(hfs_glctx PRIVATE ${HFS_OSMESA_INCLUDE_DIRS})
    target_link_libraries(hfs_glctx PRIVATE ${CMAKE_DL_LIBS})
  else()
    message(STATUS "hfshade: OSMesa not found (libosmesa6-dev); context \"osmesa\" will report \"not built\"")
  endif()
endif()
# Tests of the osmesa context exist only where it is built (tests/gl.cmake).
set(HFS_HAVE_OSMESA ${HFS_HAVE_OSMESA} CACHE INTERNAL "OSMesa context built")
if(HFS_HAVE_OSMESA)
  message(STATUS "hfshade: GL contexts: surfaceless, osmesa")
else()
  message(STATUS "hfshade: GL contexts: surfaceless (osmesa not built)")
endif()
