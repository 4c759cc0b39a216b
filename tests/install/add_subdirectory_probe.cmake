# Usage: cmake -DCMX_SOURCE_DIR=... -DWORK_DIR=... -DCXX_COMPILER=... -P add_subdirectory_probe.cmake
# A project that vendors cmx with add_subdirectory(cmx) and links cmx::cmx: configured, and its
# one source compiled against cmx::cmx's include path (<cmx/map.hpp> from the sources,
# <cmx/version.hpp> generated in the build). Linking would build the whole library (minutes), so
# that step is left to the manual check (docs: "Using cmx from another project").
file(REMOVE_RECURSE ${WORK_DIR})
file(WRITE ${WORK_DIR}/src/CMakeLists.txt "cmake_minimum_required(VERSION 3.25)
project(vendoring CXX)
set(CMX_BUILD_TESTS OFF)
set(CMX_BUILD_CLI OFF)
set(CMX_PYTHON OFF)
set(CMX_WITH_GLPK OFF)
set(CMX_WITH_TETGEN_ORACLE OFF)
add_subdirectory(\"${CMX_SOURCE_DIR}\" cmx)
add_executable(app app.cpp)
target_link_libraries(app PRIVATE cmx::cmx)
")
file(WRITE ${WORK_DIR}/src/app.cpp "#include <cmx/map.hpp>
#include <cmx/version.hpp>
static_assert(cmx::version_minor == CMX_VERSION_MINOR);
int main() { return cmx::boundary_vertices({}, 0).empty() ? 0 : 1; }
")
foreach(step "-S;${WORK_DIR}/src;-B;${WORK_DIR}/build;-DCMAKE_CXX_COMPILER=${CXX_COMPILER};-DCMAKE_POLICY_DEFAULT_CMP0077=NEW"
             "--build;${WORK_DIR}/build;--target;app.cpp.o")
  execute_process(COMMAND ${CMAKE_COMMAND} ${step} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "add_subdirectory(cmx) project: cmake ${step} failed (${rc}):\n${out}")
  endif()
endforeach()
