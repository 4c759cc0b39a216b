include(CMakePackageConfigHelpers)
install(TARGETS cmx_core EXPORT cmxTargets)
install(EXPORT cmxTargets NAMESPACE cmx:: DESTINATION lib/cmake/cmx)
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/cmxConfig.cmake.in
  ${PROJECT_BINARY_DIR}/cmxConfig.cmake INSTALL_DESTINATION lib/cmake/cmx)
# 0.x: a minor version may break the interface, so find_package(cmx 0.1) accepts 0.1.* only.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/cmxConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/cmxConfig.cmake ${PROJECT_BINARY_DIR}/cmxConfigVersion.cmake
  ${PROJECT_SOURCE_DIR}/cmake/FindCmxGmpMpfr.cmake
  DESTINATION lib/cmake/cmx)
