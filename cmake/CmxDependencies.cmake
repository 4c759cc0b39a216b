# The core links GMP (with its C++ interface) and MPFR, found by cmake/FindCmxGmpMpfr.cmake
# as imported targets, and zlib (io/ only, for compressed VTU; found in io/CMakeLists.txt).
list(PREPEND CMAKE_MODULE_PATH ${CMAKE_CURRENT_LIST_DIR})
find_package(CmxGmpMpfr REQUIRED MODULE)

if(NOT TARGET cmx_gmp)
  add_library(cmx_gmp INTERFACE)
  target_link_libraries(cmx_gmp INTERFACE CmxGmpMpfr::gmpxx CmxGmpMpfr::mpfr)
  set_target_properties(cmx_gmp PROPERTIES EXPORT_NAME gmp)
  install(TARGETS cmx_gmp EXPORT cmxTargets)
endif()

# Reference backends (never linked into the core).
if(CMX_WITH_GLPK)
  find_path(GLPK_INCLUDE_DIR glpk.h)
  find_library(GLPK_LIBRARY glpk)
  if(NOT GLPK_INCLUDE_DIR OR NOT GLPK_LIBRARY)
    message(STATUS "GLPK not found: the glpk reference backend is disabled")
    set(CMX_WITH_GLPK OFF)
  endif()
endif()
if(CMX_WITH_TETGEN_ORACLE)
  find_path(TETGEN_INCLUDE_DIR tetgen.h)
  find_library(TETGEN_LIBRARY tet)
  if(NOT TETGEN_INCLUDE_DIR OR NOT TETGEN_LIBRARY)
    message(STATUS "libtet not found: the TetGen predicate oracle is disabled")
    set(CMX_WITH_TETGEN_ORACLE OFF)
  endif()
endif()
