include(CMakePackageConfigHelpers)
install(TARGETS cmx_core EXPORT cmxTargets)
install(EXPORT cmxTargets NAMESPACE cmx:: DESTINATION lib/cmake/cmx)
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/cmxConfig.cmake.in
  ${PROJECT_BINARY_DIR}/cmxConfig.cmake INSTALL_DESTINATION lib/cmake/cmx)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/cmxConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/cmxConfig.cmake ${PROJECT_BINARY_DIR}/cmxConfigVersion.cmake
  DESTINATION lib/cmake/cmx)
