# The version cmx reports (`cmx --version`, `cmx CMD --version`, every JSON report):
# `git describe --tags --always --dirty` of the source tree, or the project version when the
# sources are not a git checkout of their own or git fails. Taken at configure time and again at
# every build (cli/CMakeLists.txt, target cmx_version_header), so that a binary built after a
# commit does not report the commit the build folder was configured at. Runs as a script:
#   cmake -DCMX_VERSION_SOURCE_DIR=DIR -DCMX_VERSION_FALLBACK=X.Y.Z -P cmake/CmxVersion.cmake
# prints the version (tests/cli checks the fallback that way); with
# -DCMX_VERSION_TEMPLATE=IN -DCMX_VERSION_OUTPUT=OUT it writes IN configured with it to OUT
# instead, only when OUT's text changes (so that nothing recompiles when the version is the same).
function(cmx_describe_version out source_dir fallback)
  set(version "${fallback}")
  find_package(Git QUIET)
  if(GIT_EXECUTABLE)
    execute_process(COMMAND "${GIT_EXECUTABLE}" -C "${source_dir}" rev-parse --show-toplevel
      OUTPUT_VARIABLE top RESULT_VARIABLE top_failed OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
    if(NOT top_failed)
      # Sources unpacked inside some other checkout must not take that checkout's version.
      file(REAL_PATH "${top}" top)
      file(REAL_PATH "${source_dir}" source)
      if(top STREQUAL source)
        execute_process(COMMAND "${GIT_EXECUTABLE}" -C "${source_dir}" describe --tags --always --dirty
          OUTPUT_VARIABLE described RESULT_VARIABLE failed OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
        if(NOT failed AND described MATCHES "^[0-9A-Za-z._+-]+$")
          set(version "${described}")
        endif()
      endif()
    endif()
  endif()
  set(${out} "${version}" PARENT_SCOPE)
endfunction()

if(CMAKE_SCRIPT_MODE_FILE STREQUAL CMAKE_CURRENT_LIST_FILE)
  cmx_describe_version(version "${CMX_VERSION_SOURCE_DIR}" "${CMX_VERSION_FALLBACK}")
  if(DEFINED CMX_VERSION_OUTPUT)
    set(CMX_VERSION_STRING "${version}")
    configure_file("${CMX_VERSION_TEMPLATE}" "${CMX_VERSION_OUTPUT}" @ONLY)  # untouched when unchanged
  else()
    execute_process(COMMAND "${CMAKE_COMMAND}" -E echo "${version}")
  endif()
endif()
