# Usage: cmake -DCMX_BUILD_DIR=... -DCONSUMER_SOURCE=... -DVERSION_PROBE_SOURCE=... -DWORK_DIR=...
#              -DCXX_COMPILER=... -DCXX_FLAGS=... -DLINKER_FLAGS=... -P install_and_consume.cmake
# Installs the build into a scratch prefix, builds consumer/ against it with flags chosen for
# speed (FMA contraction on where the machine has FMA), runs it and requires every check to pass;
# also checks the package's version rule and that no build-machine library path is installed.
file(REMOVE_RECURSE ${WORK_DIR})
set(prefix ${WORK_DIR}/prefix)
function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "failed (${rc}): ${ARGN}\n${out}")
  endif()
endfunction()
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

# What the exported flags cannot undo is refused when compiling (arith/ieee_semantics.hpp).
file(WRITE ${WORK_DIR}/fast_math.cpp "#include \"arith/expansion.hpp\"\n")
execute_process(COMMAND ${CXX_COMPILER} -std=c++20 -ffast-math -fsyntax-only -I${prefix}/include/cmx
                ${WORK_DIR}/fast_math.cpp RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(rc EQUAL 0 OR NOT out MATCHES "cmx needs IEEE 754")
  message(FATAL_ERROR "arith/expansion.hpp compiled with -ffast-math (status ${rc}):\n${out}")
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
