# The installed package is the public API: include/cmx/*.hpp (with the generated version.hpp) and
# cmx::cmx, plus the header-only kernel cmx::standalone_kernel (cmake/CmxStandalone.cmake). The
# layer libraries are installed only because cmx_api, a static library, needs them at link time
# (cmake/CmxFlags.cmake); their headers are not installed, nor is anything GPL (lp/glpk).
include(CMakePackageConfigHelpers)

file(GLOB cmx_public_headers CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/include/cmx/*.hpp)
install(FILES ${cmx_public_headers} ${PROJECT_BINARY_DIR}/include/cmx/version.hpp DESTINATION include/cmx)
install(TARGETS cmx_api EXPORT cmxTargets ARCHIVE DESTINATION lib)
# cmx::core stays a build-tree target (add_subdirectory users, the cli, the tests): installed it
# could offer no header, and linking every layer is what cmx::cmx already does. Not exporting it
# makes a 0.1 consumer's target_link_libraries(... cmx::core) fail at configure time, naming it.
install(EXPORT cmxTargets NAMESPACE cmx:: DESTINATION lib/cmake/cmx)
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/cmxConfig.cmake.in
  ${PROJECT_BINARY_DIR}/cmxConfig.cmake INSTALL_DESTINATION lib/cmake/cmx)
# 0.x: a minor version may break the interface, so find_package(cmx 0.3) accepts 0.3.* only.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/cmxConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/cmxConfig.cmake ${PROJECT_BINARY_DIR}/cmxConfigVersion.cmake
  ${PROJECT_SOURCE_DIR}/cmake/FindCmxGmpMpfr.cmake
  DESTINATION lib/cmake/cmx)

# pkg-config: the static libraries in link order (a user before what it uses; the order of
# cmx_api's private links in api/CMakeLists.txt); a layer without sources has no library.
set(CMX_PC_LIBS "")
foreach(target cmx_api cmx_algorithm cmx_generators cmx_io cmx_lp cmx_topology cmx_kernel cmx_arith)
  get_target_property(type ${target} TYPE)
  if(type STREQUAL "STATIC_LIBRARY")
    string(APPEND CMX_PC_LIBS " -l${target}")
  endif()
endforeach()
string(STRIP "${CMX_PC_LIBS}" CMX_PC_LIBS)
configure_file(${PROJECT_SOURCE_DIR}/cmake/cmx.pc.in ${PROJECT_BINARY_DIR}/cmx.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/cmx.pc DESTINATION lib/pkgconfig)
