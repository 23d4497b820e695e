# package.cmake — `cpack -G DEB` in the build directory makes five Debian
# packages, one per install component (cmake/install.cmake):
#   libhfshade0     the shared libraries (libhfshade, libhfshade_gis)
#                                                   Depends: from dpkg-shlibdeps
#   libhfshade-dev  headers, .pc, CMake package     Depends: libhfshade0 (= version)
#   hfshade-tools   hfshade, hfgen, hfbench         Depends: from dpkg-shlibdeps,
#                                                   libgdal (loaded, not linked)
#   hfshade-kiosk   the kiosk, its unit, /etc/hfshade/ (conffiles), demo data
#                                                   Depends: dpkg-shlibdeps, adduser,
#                                                   libgdal
#   python3-hfshade the Python module               Depends: libhfshade0 (= version),
#                                                   python3-numpy, python3-cffi
# The tools and the kiosk link the core statically (runtime/shared.cmake), so
# they do not depend on libhfshade0.  Packages install under /usr, the
# configuration in /etc and the unit in /lib/systemd/system whatever prefix
# the build was configured with (cmake/install_time.cmake, CPACK_SET_DESTDIR).
# tests/package.sh builds them and checks contents and control fields.
set(CPACK_PACKAGE_NAME hfshade)
set(CPACK_PACKAGE_VENDOR "hfshade")
# Who signs the packages: set it when building packages to ship.
set(HFS_DEB_MAINTAINER "hfshade maintainers <hfshade@example.org>" CACHE STRING
    "Maintainer field of the Debian packages")
set(CPACK_PACKAGE_CONTACT "${HFS_DEB_MAINTAINER}")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "soft shadows on dynamic height fields (OpenGL ES 3)")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_INSTALL_PREFIX /usr)   # the prefix install rules see under cpack
set(CPACK_SET_DESTDIR ON)        # ... and DESTDIR the staging directory
set(CPACK_STRIP_FILES ON)
set(CPACK_COMPONENTS_ALL runtime dev tools kiosk python)

set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION ON)

set(CPACK_DEBIAN_RUNTIME_PACKAGE_NAME libhfshade${PROJECT_VERSION_MAJOR})
set(CPACK_DEBIAN_RUNTIME_PACKAGE_SECTION libs)
set(CPACK_DEBIAN_PACKAGE_GENERATE_SHLIBS ON)   # shlibs + ldconfig trigger
set(CPACK_DEBIAN_PACKAGE_GENERATE_SHLIBS_POLICY ">=")
# ldconfig through the trigger, as Debian policy 8.1.1 asks (CPack's own
# postinst/postrm call it too: a lintian warning, not an error).
configure_file(${PROJECT_SOURCE_DIR}/cmake/deb/runtime-triggers ${PROJECT_BINARY_DIR}/deb/runtime/triggers COPYONLY)
set(CPACK_DEBIAN_RUNTIME_PACKAGE_CONTROL_EXTRA ${PROJECT_BINARY_DIR}/deb/runtime/triggers)
# libEGL is linked; a driver (Mesa's, or the board's) is what makes contexts.
set(CPACK_DEBIAN_RUNTIME_PACKAGE_RECOMMENDS "libegl-mesa0 | libegl-vendor")
set(CPACK_COMPONENT_RUNTIME_DESCRIPTION
"soft shadows on dynamic height fields - shared library
 hfshade lights height fields (terrain, panels) with environment maps,
 distant key lights and local spherical lights, with soft shadows, on
 OpenGL ES 3.0 (EGL) or on the CPU.")

set(CPACK_DEBIAN_DEV_PACKAGE_NAME libhfshade-dev)
set(CPACK_DEBIAN_DEV_PACKAGE_SECTION libdevel)
set(CPACK_DEBIAN_DEV_PACKAGE_DEPENDS
    "libhfshade${PROJECT_VERSION_MAJOR} (= ${PROJECT_VERSION})")
set(CPACK_COMPONENT_DEV_DESCRIPTION
"soft shadows on dynamic height fields - development files
 Headers, pkg-config file (hfshade.pc) and CMake package
 (find_package(hfshade), target hfshade::hfshade) of libhfshade.")

set(CPACK_DEBIAN_PYTHON_PACKAGE_NAME python3-hfshade)
set(CPACK_DEBIAN_PYTHON_PACKAGE_SECTION python)
set(CPACK_DEBIAN_PYTHON_PACKAGE_ARCHITECTURE all)
set(CPACK_DEBIAN_PYTHON_PACKAGE_SHLIBDEPS OFF)
set(CPACK_DEBIAN_PYTHON_PACKAGE_DEPENDS
    "libhfshade${PROJECT_VERSION_MAJOR} (= ${PROJECT_VERSION}), python3:any, python3-numpy, python3-cffi")
set(CPACK_DEBIAN_PYTHON_PACKAGE_SUGGESTS "python3-gdal")
set(CPACK_COMPONENT_PYTHON_DESCRIPTION
"soft shadows on dynamic height fields - Python 3 module
 The hfshade module renders height fields (numpy arrays in and out) and
 computes the GIS rasters of DEMs (sky-view factor, horizon angle,
 openness) and environment-map decompositions through libhfshade, with
 the same numbers as the hfshade command.")

set(CPACK_DEBIAN_TOOLS_PACKAGE_NAME hfshade-tools)
set(CPACK_DEBIAN_TOOLS_PACKAGE_SUGGESTS "gnuplot-nox")
set(CPACK_COMPONENT_TOOLS_DESCRIPTION
"soft shadows on dynamic height fields - command-line tools
 hfshade renders, compares and checks scenes (PNG/PFM/EXR, GLES or CPU);
 hfgen makes procedural height fields and skies; hfbench measures.")

set(CPACK_DEBIAN_KIOSK_PACKAGE_NAME hfshade-kiosk)
set(CPACK_DEBIAN_KIOSK_PACKAGE_DEPENDS "adduser")
# The tools and the kiosk load GDAL when they first need it
# (tools/gdal/gdal_lazy.h), so dpkg-shlibdeps does not see it: its
# package, by the file the build found, at least the version built on.
if(HFS_GDAL_FILE)
  execute_process(COMMAND dpkg-query -S ${HFS_GDAL_FILE} OUTPUT_VARIABLE hfs_gdal_owner
                  RESULT_VARIABLE hfs_gdal_rc ERROR_QUIET)
  if(hfs_gdal_rc EQUAL 0 AND hfs_gdal_owner MATCHES "^([^:, ]+)")
    set(hfs_gdal_dep "${CMAKE_MATCH_1} (>= ${HFS_GDAL_VERSION})")
    set(CPACK_DEBIAN_TOOLS_PACKAGE_DEPENDS "${hfs_gdal_dep}")
    set(CPACK_DEBIAN_KIOSK_PACKAGE_DEPENDS "adduser, ${hfs_gdal_dep}")
  endif()
endif()
configure_file(${PROJECT_SOURCE_DIR}/cmake/deb/kiosk-postinst ${PROJECT_BINARY_DIR}/deb/kiosk/postinst COPYONLY)
configure_file(${PROJECT_SOURCE_DIR}/cmake/deb/kiosk-conffiles ${PROJECT_BINARY_DIR}/deb/kiosk/conffiles COPYONLY)
set(CPACK_DEBIAN_KIOSK_PACKAGE_CONTROL_EXTRA
    ${PROJECT_BINARY_DIR}/deb/kiosk/postinst ${PROJECT_BINARY_DIR}/deb/kiosk/conffiles)
set(CPACK_COMPONENT_KIOSK_DESCRIPTION
"soft shadows on dynamic height fields - display kiosk
 hfshade-kiosk shows a lit height field full screen (KMS, X11) and turns its
 lights with knobs and buttons (GPIO, evdev) or a depth camera.  Ships a
 systemd unit (not enabled) and its configuration in /etc/hfshade/.")

# Every package's /usr/share/doc/PACKAGE/{copyright,changelog.gz}, as Debian
# policy 12.5 and 12.7 ask: cmake/deb/copyright, and a Debian-format
# changelog made from CHANGELOG.md's sections (a native package's
# changelog), gzip -9n.  `cmake --install` installs them too.
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/CHANGELOG.md)
file(STRINGS ${PROJECT_SOURCE_DIR}/CHANGELOG.md hfs_sections REGEX "^### ")
string(TIMESTAMP hfs_date "%a, %d %b %Y %H:%M:%S +0000" UTC)
set(hfs_changelog "")
foreach(component runtime dev tools kiosk python)
  string(TOUPPER ${component} upper)
  set(package ${CPACK_DEBIAN_${upper}_PACKAGE_NAME})
  set(text "${package} (${PROJECT_VERSION}) unstable; urgency=medium\n\n")
  foreach(section IN LISTS hfs_sections)
    string(REGEX REPLACE "^### +" "" section "${section}")
    string(APPEND text "  * ${section}\n")
  endforeach()
  string(APPEND text "  * The whole history, by issue: CHANGELOG.md in the source.\n\n")
  string(APPEND text " -- ${HFS_DEB_MAINTAINER}  ${hfs_date}\n")
  string(REPLACE "\n" "
" text "${text}")
  set(dir ${PROJECT_BINARY_DIR}/deb/${component}/doc)
  file(MAKE_DIRECTORY ${dir})
  file(WRITE ${dir}/changelog "${text}")
  execute_process(COMMAND gzip -9nf ${dir}/changelog RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "gzip -9n ${dir}/changelog failed")
  endif()
  install(FILES ${dir}/changelog.gz ${PROJECT_SOURCE_DIR}/cmake/deb/copyright
          DESTINATION ${CMAKE_INSTALL_DATADIR}/doc/${package} COMPONENT ${component})
endforeach()

include(CPack)
