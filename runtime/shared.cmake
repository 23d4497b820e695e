# shared.cmake — hfshade_shared: the installed shared library libhfshade.so.MAJOR
# (SONAME from project(hfshade VERSION ...)).  It is made of the objects of
# the core static modules (hfshade_lib and what it links: hfs_gles, hfs_gl,
# hfs_cpu, hfs_truth, hfs_core, hfs_sh; and hfs_envmap, whose environment-map
# functions hfshade_envmap.h exports), so nothing is
# compiled twice.  Everything is compiled with hidden visibility
# (CMAKE_C_VISIBILITY_PRESET in the top-level CMakeLists.txt) and
# position-independent: the library exports exactly the functions hfshade.h
# marks HFS_API (tests/install.sh checks it with nm -D).  It needs only
# libc, libm and libEGL (GL entry points come from the context; OSMesa is
# dlopen'ed): the file formats (hfshade_io: libpng, OpenEXR, inih) are not
# in it — the tools and the kiosk link them, and the core modules, statically.
#
# The static modules stay what the tools and tests link: they use internal
# interfaces (scene loader, SH, contexts) that the shared library hides.
# Included from runtime/CMakeLists.txt after the module folders.

set(HFS_CORE_MODULES hfshade_lib hfs_envmap hfs_gles hfs_gl hfs_cpu hfs_truth hfs_core hfs_sh)
set(hfs_core_objects "")
foreach(module IN LISTS HFS_CORE_MODULES)
  list(APPEND hfs_core_objects $<TARGET_OBJECTS:${module}>)
endforeach()

add_library(hfshade_shared SHARED ${hfs_core_objects})
# (the target "hfshade" is the command-line tool; consumers see
# hfshade::hfshade through find_package, and this alias in the build tree)
add_library(hfshade::hfshade ALIAS hfshade_shared)
add_dependencies(hfshade_shared ${HFS_CORE_MODULES})
set_target_properties(hfshade_shared PROPERTIES
  OUTPUT_NAME hfshade
  VERSION ${PROJECT_VERSION}
  SOVERSION ${PROJECT_VERSION_MAJOR}
  EXPORT_NAME hfshade
  LINKER_LANGUAGE C)
target_link_libraries(hfshade_shared PRIVATE PkgConfig::HFS_EGL Threads::Threads m ${CMAKE_DL_LIBS})
if(NOT HFS_SANITIZE)
  # Every symbol resolved at link time (the sanitizer runtimes are not).
  target_link_options(hfshade_shared PRIVATE -Wl,--no-undefined -Wl,--as-needed)
endif()
target_include_directories(hfshade_shared INTERFACE
  $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}>
  $<BUILD_INTERFACE:${HFS_GENERATED_INCLUDE}>
  $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}/hfshade>
  $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
# The public headers, installed to include/hfshade/ (cmake/install.cmake).
set(HFS_PUBLIC_HEADERS ${CMAKE_CURRENT_SOURCE_DIR}/hfshade.h ${CMAKE_CURRENT_SOURCE_DIR}/hfshade_inputs.h
    ${CMAKE_CURRENT_SOURCE_DIR}/hfshade_horizons.h ${CMAKE_CURRENT_SOURCE_DIR}/hfshade_envmap.h
    ${HFS_GENERATED_INCLUDE}/hfshade_version.h CACHE INTERNAL "Installed headers")
