# install.cmake — what `cmake --install` puts where (docs/INSTALL.md), in five
# components, one Debian package each (cmake/package.cmake):
#   runtime  libhfshade.so.MAJOR.MINOR.PATCH and its SONAME link,
#            libhfshade_gis.so.* likewise (the GIS products)       libhfshade0
#   dev      include/hfshade/{hfshade.h,hfshade_inputs.h,hfshade_horizons.h,
#            hfshade_envmap.h,hfshade_version.h,hfshade_gis.h}, the .so links,
#            lib/pkgconfig/hfshade.pc, lib/cmake/hfshade/          libhfshade-dev
#   python   lib/python3/dist-packages/hfshade/ (Debian's path for
#            modules of every Python 3), docs/PYTHON.md's example   python3-hfshade
#   tools    bin/{hfshade,hfgen,hfbench}                           hfshade-tools
#   kiosk    bin/{hfshade-kiosk,hfs-capture-info,hfs-capture-synth},
#            SYSCONFDIR/hfshade/{kiosk.ini,demo.ini}, the systemd unit,
#            share/hfshade/ (the demo's DEM and sky), its docs      hfshade-kiosk
# (and share/doc/PACKAGE/{copyright,changelog.gz} for each: cmake/package.cmake)
# Paths that depend on the prefix chosen at install time (`--prefix`, or
# /usr under cpack) — the unit's ExecStart, /etc versus PREFIX/etc, the
# .pc file — are written at install time by cmake/install_time.cmake.
include(CMakePackageConfigHelpers)

set(HFS_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/hfshade)

# ---- runtime + dev: the library -------------------------------------------
install(TARGETS hfshade_shared EXPORT hfshadeTargets
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT runtime
                NAMELINK_COMPONENT dev)
install(FILES ${HFS_PUBLIC_HEADERS} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/hfshade
        COMPONENT dev)
# libhfshade_gis (tools/gis_shared.cmake) beside it; its header with the others.
install(TARGETS hfshade_gis_shared
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT runtime
                NAMELINK_COMPONENT dev)
install(FILES ${HFS_GIS_PUBLIC_HEADERS} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/hfshade
        COMPONENT dev)

# ---- python: the hfshade module (tools/python/hfshade, docs/PYTHON.md) -----
# Debian's place for pure modules of every Python 3 (not the prefix's
# python3.X/site-packages): PREFIX/lib/python3/dist-packages, so that the
# package under /usr is on Debian's python3's path.  The module finds the
# libraries by their SONAMEs.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/tools/python/hfshade
        DESTINATION lib/python3/dist-packages COMPONENT python
        FILES_MATCHING PATTERN "*.py" PATTERN "__pycache__" EXCLUDE)
install(PROGRAMS ${PROJECT_SOURCE_DIR}/tools/examples/python/svf_geotiff.py
        DESTINATION ${CMAKE_INSTALL_DATADIR}/doc/python3-hfshade/examples COMPONENT python)
install(EXPORT hfshadeTargets NAMESPACE hfshade:: DESTINATION ${HFS_INSTALL_CMAKEDIR}
        COMPONENT dev)
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/hfshadeConfig.cmake.in
  ${PROJECT_BINARY_DIR}/cmake/hfshadeConfig.cmake INSTALL_DESTINATION ${HFS_INSTALL_CMAKEDIR})
# The SONAME changes with the major version: so does compatibility.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/cmake/hfshadeConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMajorVersion)
install(FILES ${PROJECT_BINARY_DIR}/cmake/hfshadeConfig.cmake
              ${PROJECT_BINARY_DIR}/cmake/hfshadeConfigVersion.cmake
        DESTINATION ${HFS_INSTALL_CMAKEDIR} COMPONENT dev)

# ---- tools and kiosk: statically linked against the core modules ----------
# (they use internal interfaces the shared library hides: runtime/shared.cmake)
install(TARGETS hfshade hfgen hfbench RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
        COMPONENT tools)
install(TARGETS hfshade-kiosk hfs-capture-info hfs-capture-synth
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT kiosk)
install(FILES ${PROJECT_SOURCE_DIR}/data/jacksboro.png ${PROJECT_SOURCE_DIR}/data/courtyard.exr
              ${PROJECT_SOURCE_DIR}/data/demo.ini ${PROJECT_SOURCE_DIR}/data/demo-objects.txt
        DESTINATION ${CMAKE_INSTALL_DATADIR}/hfshade COMPONENT kiosk)
install(FILES ${PROJECT_SOURCE_DIR}/board/KIOSK.md ${PROJECT_SOURCE_DIR}/docs/INPUT.md
        DESTINATION ${CMAKE_INSTALL_DATADIR}/doc/hfshade-kiosk COMPONENT kiosk)

# ---- files whose contents or place depend on the install-time prefix --------
foreach(component dev kiosk)
  install(CODE "
    set(HFS_COMPONENT ${component})
    set(HFS_SOURCE_DIR \"${PROJECT_SOURCE_DIR}\")
    set(HFS_GEN_DIR \"${PROJECT_BINARY_DIR}/install-gen\")
    set(HFS_VERSION \"${PROJECT_VERSION}\")
    set(HFS_LIBDIR \"${CMAKE_INSTALL_LIBDIR}\")
    set(HFS_INCLUDEDIR \"${CMAKE_INSTALL_INCLUDEDIR}\")
    set(HFS_BINDIR \"${CMAKE_INSTALL_BINDIR}\")
    set(HFS_DATADIR \"${CMAKE_INSTALL_DATADIR}\")
    include(\"${PROJECT_SOURCE_DIR}/cmake/install_time.cmake\")
  " COMPONENT ${component})
endforeach()
