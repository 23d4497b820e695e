# install.cmake — the installed package, used as someone else would
# (tests/install.sh: places, SONAME, NEEDED, exported symbols, consumers
# through pkg-config and find_package) and the Debian packages
# (tests/package.sh: cpack -G DEB, contents, control fields).
# Not under the sanitizers: a program of someone else's, built without
# -fsanitize, cannot load a sanitized libhfshade (the sanitizer runtime must
# come first); the other two suites of .ci/run run them.
if(NOT HFS_SANITIZE)
  add_test(NAME install_consumer
           COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/install.sh ${PROJECT_BINARY_DIR}
                   ${PROJECT_SOURCE_DIR} ${PROJECT_VERSION})
  set_tests_properties(install_consumer PROPERTIES LABELS "install;gl" TIMEOUT 180)
endif()
if(NOT HFS_SANITIZE)
  add_test(NAME package_deb
           COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/package.sh ${PROJECT_BINARY_DIR} ${PROJECT_VERSION})
  set_tests_properties(package_deb PROPERTIES LABELS install TIMEOUT 300)
endif()
