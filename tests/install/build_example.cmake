# Usage: cmake -DCMX_BUILD_DIR=... -DEXAMPLE_SOURCE=... -DWORK_DIR=... -DCXX_COMPILER=...
#              [-DCXX_FLAGS=... -DLINKER_FLAGS=...] -P build_example.cmake
# Installs the build into a scratch prefix, builds examples/cpp against it as a user would
# (find_package(cmx 0.3), nothing but the install), runs it and requires an exact-valid map.
cmake_minimum_required(VERSION 3.25)  # script mode: the policies of the project (IN_LIST)
file(REMOVE_RECURSE ${WORK_DIR})
include(${CMAKE_CURRENT_LIST_DIR}/run_command.cmake)
run(${CMAKE_COMMAND} --install ${CMX_BUILD_DIR} --prefix ${WORK_DIR}/prefix)
run(${CMAKE_COMMAND} -S ${EXAMPLE_SOURCE} -B ${WORK_DIR}/build -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix
    -DCMAKE_CXX_COMPILER=${CXX_COMPILER} "-DCMAKE_CXX_FLAGS=${CXX_FLAGS}" "-DCMAKE_EXE_LINKER_FLAGS=${LINKER_FLAGS}")
run(${CMAKE_COMMAND} --build ${WORK_DIR}/build)
execute_process(COMMAND ${WORK_DIR}/build/map_ball RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
message(STATUS "examples/cpp/map_ball:\n${out}")
if(NOT rc EQUAL 0 OR NOT out MATCHES "status: success" OR NOT out MATCHES "exact_valid: yes")
  message(FATAL_ERROR "map_ball ran with status ${rc} and did not report an exact-valid map")
endif()
