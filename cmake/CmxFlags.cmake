# Build flags are part of correctness: fused multiply-add contraction breaks Two-Product (and
# everything built on it, arith/expansion.hpp), and the interval arithmetic changes the rounding
# mode, which the optimiser must respect. tests/kernel/test_fp_contract.cpp fails if this is lost.
# They hold for every translation unit of the build, and through cmx_fp_model (linked by every
# layer, exported as cmx::fp_model) for every target that links an installed cmx target: the
# installed header-only kernel (cmx::standalone_kernel) is inline floating-point code that needs
# them (docs/DESIGN.md, "Layers and build"), and a consumer's -ffp-contract=fast in
# CMAKE_CXX_FLAGS comes before them on the command line.
# MSVC would need /fp:strict (no contraction, the rounding mode honoured), but the interval code
# uses GCC builtins and inline assembly (arith/interval.hpp), so cmx does not build there anyway.
set(cmx_gnu_like "$<COMPILE_LANG_AND_ID:CXX,GNU,Clang,AppleClang>")
set(CMX_FP_OPTIONS "$<${cmx_gnu_like}:-ffp-contract=off>" "$<${cmx_gnu_like}:-frounding-math>")
add_compile_options(${CMX_FP_OPTIONS})
add_library(cmx_fp_model INTERFACE)
target_compile_options(cmx_fp_model INTERFACE ${CMX_FP_OPTIONS})
set_target_properties(cmx_fp_model PROPERTIES EXPORT_NAME fp_model)
install(TARGETS cmx_fp_model EXPORT cmxTargets)

if(CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
  add_compile_options(-Wall -Wextra -Wpedantic)
  if(CMX_WERROR)
    add_compile_options(-Werror)
  endif()
endif()
if(NOT CMAKE_BUILD_TYPE AND NOT CMAKE_CONFIGURATION_TYPES)
  set(CMAKE_BUILD_TYPE Release CACHE STRING "Build type" FORCE)
endif()

# Adds a library layer: cmx_<name> with alias cmx::<name>. Sources are every *.cpp of the layer's
# folder and of the subfolders named by SUBDIRS (one concept per file; no list to keep in sync).
# The layers' headers are not installed: the installed package's API is include/cmx/*.hpp
# (cmx::cmx, cmake/CmxInstall.cmake). The static libraries are installed and exported all the
# same, because cmx_api links them privately and a static library's private dependencies are
# still linked by its users ($<LINK_ONLY:...> in the export); their include directory is the
# source tree only, so an installed layer target brings no header and no include path.
function(cmx_add_layer name)
  cmake_parse_arguments(L "" "" "DEPS;SUBDIRS" ${ARGN})
  file(GLOB sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/*.cpp)
  foreach(sub IN LISTS L_SUBDIRS)
    file(GLOB sub_sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/${sub}/*.cpp)
    list(APPEND sources ${sub_sources})
  endforeach()
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
  target_include_directories(cmx_${name} ${scope} $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}>)
  target_link_libraries(cmx_${name} ${scope} cmx_fp_model ${L_DEPS})
  install(TARGETS cmx_${name} EXPORT cmxTargets ARCHIVE DESTINATION lib)
endfunction()
