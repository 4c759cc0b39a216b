# Finds GMP with its C++ interface (gmpxx) and MPFR, which ship no CMake package on Debian, and
# defines the imported targets CmxGmpMpfr::gmpxx, CmxGmpMpfr::mpfr and CmxGmpMpfr::gmp (the
# first two bring the last). The build uses it (cmake/CmxDependencies.cmake) and so does the
# installed cmxConfig.cmake, beside which it is installed: the exported targets name these
# imported targets, so the installed package finds the libraries again on the machine that uses
# it instead of carrying the build machine's paths.
find_path(CmxGmpMpfr_GMP_INCLUDE_DIR gmpxx.h)
find_path(CmxGmpMpfr_MPFR_INCLUDE_DIR mpfr.h)
find_library(CmxGmpMpfr_GMP_LIBRARY gmp)
find_library(CmxGmpMpfr_GMPXX_LIBRARY gmpxx)
find_library(CmxGmpMpfr_MPFR_LIBRARY mpfr)
mark_as_advanced(CmxGmpMpfr_GMP_INCLUDE_DIR CmxGmpMpfr_MPFR_INCLUDE_DIR CmxGmpMpfr_GMP_LIBRARY
                 CmxGmpMpfr_GMPXX_LIBRARY CmxGmpMpfr_MPFR_LIBRARY)

include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(CmxGmpMpfr
  REQUIRED_VARS CmxGmpMpfr_GMPXX_LIBRARY CmxGmpMpfr_GMP_LIBRARY CmxGmpMpfr_MPFR_LIBRARY
                CmxGmpMpfr_GMP_INCLUDE_DIR CmxGmpMpfr_MPFR_INCLUDE_DIR
  REASON_FAILURE_MESSAGE "cmx needs GMP with gmpxx and MPFR (Debian: libgmp-dev libmpfr-dev)")

if(CmxGmpMpfr_FOUND)
  # name, library, header folder, libraries it needs
  foreach(spec "gmp;GMP;GMP;" "gmpxx;GMPXX;GMP;CmxGmpMpfr::gmp" "mpfr;MPFR;MPFR;CmxGmpMpfr::gmp")
    list(GET spec 0 name)
    list(GET spec 1 library)
    list(GET spec 2 headers)
    list(GET spec 3 needs)
    if(NOT TARGET CmxGmpMpfr::${name})
      add_library(CmxGmpMpfr::${name} UNKNOWN IMPORTED)
      set_target_properties(CmxGmpMpfr::${name} PROPERTIES
        IMPORTED_LOCATION "${CmxGmpMpfr_${library}_LIBRARY}"
        INTERFACE_INCLUDE_DIRECTORIES "${CmxGmpMpfr_${headers}_INCLUDE_DIR}"
        INTERFACE_LINK_LIBRARIES "${needs}")
    endif()
  endforeach()
endif()
