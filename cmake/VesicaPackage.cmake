# Install: `cmake --install build --prefix P` (make install PREFIX=P). Included at the end
# of the top-level CMakeLists.txt, when every library and executable has registered its
# own install rules (VesicaTargets.cmake).
include(CMakePackageConfigHelpers)

set(VESICA_INSTALL_DATADIR ${CMAKE_INSTALL_DATADIR}/vesica)
set(VESICA_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/vesica)

# The example pipelines keep their data beside them (demo.yaml reads data/*.csv).
install(FILES pipelines/demo.yaml pipelines/neobladder-whatif.yaml
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
