# install_time.cmake — run by `cmake --install` / cpack (cmake/install.cmake)
# for the files whose contents or place depend on the prefix known only at
# install time.  GNUInstallDirs' rules, applied then:
#   SYSCONFDIR  /etc when the prefix is /usr, else PREFIX/etc;
#   systemd     /lib/systemd/system when the prefix is /usr (Debian 12 keeps
#               units there), else PREFIX/lib/systemd/system (systemd also
#               reads /usr/local/lib/systemd/system).
# file(INSTALL) honours DESTDIR, as every other install rule does.
set(prefix "${CMAKE_INSTALL_PREFIX}")
string(REGEX REPLACE "/+$" "" prefix "${prefix}")
if(prefix STREQUAL "/usr")
  set(sysconfdir "/etc")
  set(unitdir "/lib/systemd/system")
else()
  set(sysconfdir "${prefix}/etc")
  set(unitdir "${prefix}/lib/systemd/system")
endif()
set(gen "${HFS_GEN_DIR}/${HFS_COMPONENT}")
file(MAKE_DIRECTORY "${gen}")

if(HFS_COMPONENT STREQUAL "dev")
  set(HFS_PREFIX "${prefix}")
  file(READ "${HFS_SOURCE_DIR}/cmake/hfshade.pc.in" pc)
  string(CONFIGURE "${pc}" pc @ONLY)
  file(WRITE "${gen}/hfshade.pc" "${pc}")
  file(INSTALL DESTINATION "${prefix}/${HFS_LIBDIR}/pkgconfig" TYPE FILE FILES "${gen}/hfshade.pc")
elseif(HFS_COMPONENT STREQUAL "kiosk")
  set(bindir "${prefix}/${HFS_BINDIR}")
  set(datadir "${prefix}/${HFS_DATADIR}/hfshade")
  # The demo scene, its data in DATADIR/hfshade/ (not configuration).
  file(READ "${HFS_SOURCE_DIR}/data/demo.ini" scene)
  string(REPLACE "height = jacksboro.png" "height = ${datadir}/jacksboro.png" scene "${scene}")
  string(REPLACE "env-map = courtyard.exr" "env-map = ${datadir}/courtyard.exr" scene "${scene}")
  string(FIND "${scene}" "height = ${datadir}/jacksboro.png" at_height)
  string(FIND "${scene}" "env-map = ${datadir}/courtyard.exr" at_env)
  if(at_height LESS 0 OR at_env LESS 0)
    message(FATAL_ERROR "install_time.cmake: data/demo.ini no longer names jacksboro.png and courtyard.exr as expected")
  endif()
  file(WRITE "${gen}/demo.ini" "${scene}")
  file(INSTALL DESTINATION "${sysconfdir}/hfshade" TYPE FILE
       FILES "${gen}/demo.ini" "${HFS_SOURCE_DIR}/board/kiosk.ini")
  # The unit, pointing at this prefix's kiosk and configuration.
  file(READ "${HFS_SOURCE_DIR}/board/hfshade-kiosk.service" unit)
  string(REPLACE "/usr/local/bin/hfshade-kiosk" "${bindir}/hfshade-kiosk" unit "${unit}")
  string(REPLACE "/etc/hfshade/" "${sysconfdir}/hfshade/" unit "${unit}")
  string(REPLACE "file:/usr/local/share/doc/hfshade/KIOSK.md"
                 "file:${prefix}/${HFS_DATADIR}/doc/hfshade-kiosk/KIOSK.md" unit "${unit}")
  string(FIND "${unit}" "ExecStart=${bindir}/hfshade-kiosk ${sysconfdir}/hfshade/demo.ini" at_exec)
  if(at_exec LESS 0)
    message(FATAL_ERROR "install_time.cmake: board/hfshade-kiosk.service's ExecStart is not the expected one")
  endif()
  file(WRITE "${gen}/hfshade-kiosk.service" "${unit}")
  file(INSTALL DESTINATION "${unitdir}" TYPE FILE FILES "${gen}/hfshade-kiosk.service")
endif()
