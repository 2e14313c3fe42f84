# Install and package: `cmake --install build --prefix P` (make install PREFIX=P) and
# `cpack -G DEB` (make package). Included at the end of the top-level CMakeLists.txt, when
# every library and executable has registered its own install rules (VesicaTargets.cmake).
#
# Two Debian packages, as Debian splits a library:
#   vesica      (component Runtime)     bin/vesica*, share/vesica (example pipelines and
#                                       their data), share/doc/vesica; depends on the
#                                       runtime libraries the executables link
#                                       (dpkg-shlibdeps).
#   vesica-dev  (component Development) the static libraries, public headers and the CMake
#                                       package lib/cmake/vesica; depends on vesica and on
#                                       the -dev packages a consumer compiles against.
include(CMakePackageConfigHelpers)

set(VESICA_INSTALL_DATADIR ${CMAKE_INSTALL_DATADIR}/vesica)
set(VESICA_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/vesica)

# The example pipelines keep their data beside them (demo.yaml reads data/*.csv).
install(FILES pipelines/demo.yaml pipelines/neobladder-whatif.yaml pipelines/mr-demo.yaml
  DESTINATION ${VESICA_INSTALL_DATADIR}/pipelines COMPONENT Runtime)
install(DIRECTORY pipelines/data/
  DESTINATION ${VESICA_INSTALL_DATADIR}/pipelines/data COMPONENT Runtime)
install(FILES LICENSE CITATION.cff README.md
  DESTINATION ${CMAKE_INSTALL_DOCDIR} COMPONENT Runtime)

install(EXPORT vesicaTargets NAMESPACE vesica::
  DESTINATION ${VESICA_INSTALL_CMAKEDIR} COMPONENT Development)
configure_package_config_file(cmake/vesicaConfig.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/vesicaConfig.cmake
  INSTALL_DESTINATION ${VESICA_INSTALL_CMAKEDIR}
  PATH_VARS CMAKE_INSTALL_BINDIR VESICA_INSTALL_DATADIR)
# 0.x: a minor version may change the API.
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/vesicaConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/vesicaConfig.cmake
  ${CMAKE_CURRENT_BINARY_DIR}/vesicaConfigVersion.cmake cmake/vesicaDependencies.cmake
  DESTINATION ${VESICA_INSTALL_CMAKEDIR} COMPONENT Development)

# --- Debian packages (CPack DEB) ---
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME vesica)
set(CPACK_PACKAGE_VENDOR "The vesica developers")
set(VESICA_PACKAGE_MAINTAINER "The vesica developers <vesica@localhost>" CACHE STRING
  "Maintainer field of the Debian packages (name <email>): set it when you publish them")
set(CPACK_PACKAGE_CONTACT "${VESICA_PACKAGE_MAINTAINER}")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
  "patient CT or MRI to a simulation of the urinary bladder, checked against urodynamics")
set(CPACK_PACKAGE_DESCRIPTION
  "vesica segments the bladder in a CT or MRI, builds its wall surface and meshes, \
simulates filling and voiding (nonlinear membrane wall coupled to the urine) and compares \
the result with the patient's urodynamic recording. A chain of small executables driven \
by a pipeline file (vesica run).")
set(CPACK_RESOURCE_FILE_LICENSE ${CMAKE_CURRENT_SOURCE_DIR}/LICENSE)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)  # <name>_<version>_<arch>.deb
set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_COMPONENTS_ALL Runtime Development)
set(CPACK_DEBIAN_PACKAGE_SECTION science)

set(CPACK_DEBIAN_RUNTIME_PACKAGE_NAME vesica)
set(CPACK_DEBIAN_RUNTIME_FILE_NAME DEB-DEFAULT)
# The Depends line of the executables' shared libraries, computed by dpkg-shlibdeps.
set(CPACK_DEBIAN_RUNTIME_PACKAGE_SHLIBDEPS ON)
# Not linked, but called: xvfb-run draws the report's wall-stress picture without a
# display; headless Chromium prints the report to report.pdf; three.js (libjs-three) is
# inlined into the report for its interactive wall; Snakemake runs
# `vesica export --snakemake` workflows on a cluster.
set(CPACK_DEBIAN_RUNTIME_PACKAGE_RECOMMENDS "xvfb, xauth, chromium, libjs-three")
set(CPACK_DEBIAN_RUNTIME_PACKAGE_SUGGESTS "snakemake")

set(CPACK_DEBIAN_DEVELOPMENT_PACKAGE_NAME vesica-dev)
set(CPACK_DEBIAN_DEVELOPMENT_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_DEVELOPMENT_PACKAGE_SECTION libdevel)
set(CPACK_DEBIAN_DEVELOPMENT_PACKAGE_DEPENDS "vesica (= ${PROJECT_VERSION}), \
libinsighttoolkit5-dev, libgdcm-dev, libvtk9-dev, libcgal-dev, libgmsh-dev, libeigen3-dev, \
libsuitesparse-dev, libmumps-seq-dev, libassimp-dev, libyaml-cpp-dev, nlohmann-json3-dev, \
libcli11-dev, libfmt-dev, libspdlog-dev, libssl-dev")

include(CPack)
