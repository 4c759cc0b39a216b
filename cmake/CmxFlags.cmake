# Build flags are part of correctness: fused multiply-add contraction breaks Two-Product and the
# error bounds of the predicate filters, and the interval arithmetic changes the rounding mode,
# which the optimiser must respect. tests/kernel/test_fp_contract.cpp fails if this is lost.
add_compile_options(-ffp-contract=off -frounding-math)
if(CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
  add_compile_options(-Wall -Wextra -Wpedantic)
  if(CMX_WERROR)
    add_compile_options(-Werror)
  endif()
endif()
if(NOT CMAKE_BUILD_TYPE AND NOT CMAKE_CONFIGURATION_TYPES)
  set(CMAKE_BUILD_TYPE Release CACHE STRING "Build type" FORCE)
endif()

# Adds a library layer: cmx_<name> with alias cmx::<name>, its headers installed under include/cmx.
# Sources are every *.cpp of the layer's folder (one concept per file; no list to keep in sync).
function(cmx_add_layer name)
  cmake_parse_arguments(L "" "" "DEPS" ${ARGN})
  file(GLOB sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/*.cpp)
  set(scope PUBLIC)
  if(sources)
    add_library(cmx_${name} STATIC ${sources})
    set_target_properties(cmx_${name} PROPERTIES POSITION_INDEPENDENT_CODE ON)
  else()  # a layer with headers only (so far)
    add_library(cmx_${name} INTERFACE)
    set(scope INTERFACE)
  endif()
  add_library(cmx::${name} ALIAS cmx_${name})
  set_target_properties(cmx_${name} PROPERTIES EXPORT_NAME ${name})
  target_include_directories(cmx_${name} ${scope}
    $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}>
    $<INSTALL_INTERFACE:include/cmx>)
  target_link_libraries(cmx_${name} ${scope} ${L_DEPS})
  install(TARGETS cmx_${name} EXPORT cmxTargets ARCHIVE DESTINATION lib)
  install(DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}/ DESTINATION include/cmx/${name}
          FILES_MATCHING PATTERN "*.hpp")
endfunction()
