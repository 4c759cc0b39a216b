# Usage: cmake -DCMX_SOURCE_DIR=... -DCMX_BUILD_DIR=... -DCONSUMER_SOURCE=... -DVERSION_PROBE_SOURCE=...
#              -DWORK_DIR=... -DCXX_COMPILER=... -DCXX_FLAGS=... -DLINKER_FLAGS=...
#              [-DPKG_CONFIG=...] -P install_and_consume.cmake
# Installs the build into a scratch prefix, builds consumer/ against it with flags chosen for
# speed (FMA contraction on where the machine has FMA), runs it and requires every check to pass;
# also checks the package's version rule, which files are installed, that no build-machine library
# path is, and the same consumer built by g++ with `pkg-config --cflags --libs cmx` alone.
cmake_minimum_required(VERSION 3.25)  # script mode: the policies of the project (IN_LIST)
file(REMOVE_RECURSE ${WORK_DIR})
set(prefix ${WORK_DIR}/prefix)
include(${CMAKE_CURRENT_LIST_DIR}/run_command.cmake)
run(${CMAKE_COMMAND} --install ${CMX_BUILD_DIR} --prefix ${prefix})

# The installed package finds GMP and MPFR again on the consumer's machine: no library path of
# the build machine may be written into it.
file(GLOB package_files ${prefix}/lib/cmake/cmx/*.cmake)
foreach(f IN LISTS package_files)
  file(STRINGS ${f} absolute_libraries REGEX "/lib(gmp|gmpxx|mpfr)[.](so|a)")
  if(absolute_libraries)
    message(FATAL_ERROR "${f} names the build machine's libraries:\n${absolute_libraries}")
  endif()
endforeach()

# The installed headers are the public API (include/cmx/*.hpp from the sources, and the generated
# version.hpp) and the header-only kernel's closure under include/cmx_standalone/; nothing of a
# namespace detail under include/cmx, and nothing of the GPL GLPK backend in the headers and
# libraries (bin/cmx, the program, is installed only when built without GLPK).
file(GLOB source_headers RELATIVE ${CMX_SOURCE_DIR}/include ${CMX_SOURCE_DIR}/include/cmx/*.hpp)
file(GLOB_RECURSE standalone_headers RELATIVE ${CMX_BUILD_DIR}/standalone ${CMX_BUILD_DIR}/standalone/*)
set(expected_headers ${source_headers} cmx/version.hpp ${standalone_headers})
file(GLOB_RECURSE installed_headers RELATIVE ${prefix}/include ${prefix}/include/*)
list(SORT expected_headers)
list(SORT installed_headers)
if(NOT installed_headers STREQUAL expected_headers OR NOT "cmx_standalone/kernel/orient_standalone.hpp" IN_LIST installed_headers)
  message(FATAL_ERROR "installed headers:\n  ${installed_headers}\nexpected:\n  ${expected_headers}")
endif()
foreach(header IN LISTS installed_headers)
  file(STRINGS ${prefix}/include/${header} detail REGEX "namespace detail")
  if(header MATCHES "^cmx/" AND detail)
    message(FATAL_ERROR "${header} is installed in include/cmx and has a namespace detail")
  endif()
endforeach()
file(GLOB_RECURSE installed_files ${prefix}/include/* ${prefix}/lib/* ${prefix}/share/*)
foreach(f IN LISTS installed_files)
  file(STRINGS ${f} glpk REGEX "[Gg][Ll][Pp][Kk]")
  if(f MATCHES "glpk" OR glpk)
    message(FATAL_ERROR "${f} is or names the GLPK backend (GPL): not part of the package")
  endif()
endforeach()
# The program is installed only when it does not link GLPK (cli/CMakeLists.txt).
if(EXISTS ${prefix}/bin/cmx)
  file(STRINGS ${prefix}/bin/cmx needs_glpk REGEX "libglpk[.]so")
  if(needs_glpk)
    message(FATAL_ERROR "${prefix}/bin/cmx is installed and links GLPK (GPL)")
  endif()
endif()

# What the exported flags cannot undo is refused when compiling (arith/ieee_semantics.hpp).
file(WRITE ${WORK_DIR}/fast_math.cpp "#include <cmx_standalone/kernel/orient_standalone.hpp>\n")
execute_process(COMMAND ${CXX_COMPILER} -std=c++20 -ffast-math -fsyntax-only -I${prefix}/include
                ${WORK_DIR}/fast_math.cpp RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(rc EQUAL 0 OR NOT out MATCHES "cmx needs IEEE 754")
  message(FATAL_ERROR "the header-only kernel compiled with -ffast-math (status ${rc}):\n${out}")
endif()

run(${CMAKE_COMMAND} -S ${VERSION_PROBE_SOURCE} -B ${WORK_DIR}/version_probe -DCMAKE_PREFIX_PATH=${prefix}
    -DCMAKE_CXX_COMPILER=${CXX_COMPILER})

set(consumer_flags "${CXX_FLAGS} -O2 -march=native -ffp-contract=fast")
run(${CMAKE_COMMAND} -S ${CONSUMER_SOURCE} -B ${WORK_DIR}/build -DCMAKE_PREFIX_PATH=${prefix}
    -DCMAKE_CXX_COMPILER=${CXX_COMPILER} "-DCMAKE_CXX_FLAGS=${consumer_flags}"
    "-DCMAKE_EXE_LINKER_FLAGS=${LINKER_FLAGS}")
run(${CMAKE_COMMAND} --build ${WORK_DIR}/build)
execute_process(COMMAND ${WORK_DIR}/build/consumer RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
message(STATUS "consumer built with ${consumer_flags}, output:\n${out}")
if(NOT rc EQUAL 0 OR NOT out MATCHES "orient3d = [+]\n" OR NOT out MATCHES "all checks passed")
  message(FATAL_ERROR "consumer ran with status ${rc}")
endif()
if(out MATCHES "contract a[*]b - c: no")
  message(STATUS "note: this machine or compiler does not contract a*b - c, so the flags were not put to the test")
endif()

# The same sources built without CMake, with the flags of cmx.pc alone (its Libs must be enough to
# link the static libraries). No pkg-config on the machine: said, and skipped.
if(NOT PKG_CONFIG)
  message(STATUS "pkg-config not found: the pkg-config consumer build was skipped")
  return()
endif()
set(ENV{PKG_CONFIG_PATH} ${prefix}/lib/pkgconfig)
execute_process(COMMAND ${PKG_CONFIG} --cflags --libs cmx RESULT_VARIABLE rc OUTPUT_VARIABLE pc_flags
                ERROR_VARIABLE pc_flags OUTPUT_STRIP_TRAILING_WHITESPACE)
if(NOT rc EQUAL 0 OR NOT pc_flags MATCHES "-ffp-contract=off")
  message(FATAL_ERROR "pkg-config --cflags --libs cmx failed (${rc}): ${pc_flags}")
endif()
separate_arguments(pc_flags UNIX_COMMAND "${pc_flags}")
separate_arguments(user_flags UNIX_COMMAND "${consumer_flags} ${LINKER_FLAGS}")
# pkg-config's flags come after the user's (`g++ $CXXFLAGS app.cpp $(pkg-config ...)`), so its
# -ffp-contract=off wins; the package version is what the .pc file says.
execute_process(COMMAND ${PKG_CONFIG} --modversion cmx OUTPUT_VARIABLE pc_version OUTPUT_STRIP_TRAILING_WHITESPACE)
# The contraction probe is compiled with the user's flags alone, as in consumer/CMakeLists.txt.
run(${CXX_COMPILER} -std=c++20 ${user_flags} -c ${CONSUMER_SOURCE}/contraction_probe.cpp
    -o ${WORK_DIR}/contraction_probe.o)
file(GLOB consumer_sources ${CONSUMER_SOURCE}/*.cpp)
list(REMOVE_ITEM consumer_sources ${CONSUMER_SOURCE}/contraction_probe.cpp)
run(${CXX_COMPILER} -std=c++20 ${user_flags} -I${CONSUMER_SOURCE}/decoy "-DCMX_PACKAGE_VERSION=\"${pc_version}\""
    ${consumer_sources} ${WORK_DIR}/contraction_probe.o ${pc_flags} -o ${WORK_DIR}/pkg_config_consumer)
execute_process(COMMAND ${WORK_DIR}/pkg_config_consumer RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
message(STATUS "consumer built with pkg-config, output:\n${out}")
if(NOT rc EQUAL 0 OR NOT out MATCHES "all checks passed")
  message(FATAL_ERROR "the pkg-config consumer ran with status ${rc}")
endif()
