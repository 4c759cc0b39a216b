# Usage: cmake -DPROBE=<cmx_skip_probe> -DDATA_TESTS=<file> -DSKIP_CODE=<code> -P check_skips.cmake
# DATA_TESTS holds lines `<suite executable>|<test case>` of test cases that need ../shared.
# Checks the run-time skips of tests/main.cpp with ../shared made absent (the environment's
# CMX_SHARED_DIR): a run of one skipping test case exits SKIP_CODE (ctest's SKIP_RETURN_CODE), a failure
# outweighs a skip, a run of several exits 0 and lists each skip, and the data-dependent test
# cases skip instead of passing.
set(absent "/nonexistent/cmx-shared")
if(EXISTS ${absent})
  message(FATAL_ERROR "${absent} exists: it must not, for this test")
endif()
set(failures "")

# Runs EXE with ARGN and CMX_SHARED_DIR=absent; expects exit STATUS (`failed`: neither 0 nor SKIP_CODE)
# and output matching PATTERN.
function(expect exe status pattern)
  execute_process(COMMAND ${CMAKE_COMMAND} -E env CMX_SHARED_DIR=${absent} ${exe} ${ARGN}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(status STREQUAL "failed")
    set(ok TRUE)
    if(rc EQUAL 0 OR rc EQUAL SKIP_CODE)
      set(ok FALSE)
    endif()
  else()
    set(ok FALSE)
    if(rc EQUAL status)
      set(ok TRUE)
    endif()
  endif()
  if(NOT ok OR NOT out MATCHES "${pattern}")
    set(failures "${failures}${exe} ${ARGN}: exit ${rc}, expected ${status} and output matching ${pattern}:\n${out}\n" PARENT_SCOPE)
  endif()
endfunction()

expect(${PROBE} ${SKIP_CODE} "SKIPPED: probe: skips: the probe's reason" "--test-case=probe: skips")
expect(${PROBE} 0 "test cases: 1 [|] 1 passed" "--test-case=probe: the environment names the shared folder")
expect(${PROBE} failed "fails on purpose" "--test-case=probe: skips then fails")
expect(${PROBE} 0 "skipped at run time [(]not passed[)]: 1 test case.*SKIPPED: probe: skips: "
       "--test-case=probe: skips,probe: the environment names the shared folder")
expect(${PROBE} ${SKIP_CODE} "SKIPPED: probe: looks for shared data: no ${absent}/data" "--test-case=probe: looks for shared data")

file(STRINGS ${DATA_TESTS} lines)
foreach(line IN LISTS lines)
  string(FIND "${line}" "|" bar)
  string(SUBSTRING "${line}" 0 ${bar} exe)
  math(EXPR start "${bar} + 1")
  string(SUBSTRING "${line}" ${start} -1 name)
  string(REPLACE "," "\\," filter "${name}")  # doctest's filter separates names by commas
  expect(${exe} ${SKIP_CODE} "SKIPPED: " "--test-case=${filter}")
endforeach()

if(failures)
  message(FATAL_ERROR "${failures}")
endif()
list(LENGTH lines count)
message(STATUS "the probe's 5 runs and ${count} data-dependent test cases skip as they should")
