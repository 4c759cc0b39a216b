# Usage: cmake -P check_test_names.cmake SUITE_EXE...
# Fails if a doctest test-case name contains a character that doctest_discover_tests cannot carry
# into a ctest entry: ';' splits the name in two; an unbalanced '[' or ']' makes CMake's list
# parsing merge neighbouring names (both are refused, balanced or not); a '\' at the end of a name
# escapes the separator, and before ',' or '\' it changes doctest's --test-case filter. Such
# entries would run no test case at all. ('*', '?' and letter case matter only if a name then
# matches a second test case: each ctest entry fails unless exactly one test case ran.)
set(exes "")
set(after_script FALSE)
math(EXPR last "${CMAKE_ARGC} - 1")
foreach(i RANGE 1 ${last})
  if(after_script)
    list(APPEND exes "${CMAKE_ARGV${i}}")
  elseif(CMAKE_ARGV${i} MATCHES "check_test_names[.]cmake$")
    set(after_script TRUE)
  endif()
endforeach()
if(NOT exes)
  message(FATAL_ERROR "no test executables given")
endif()

set(bad_names "")
set(checked 0)
foreach(exe IN LISTS exes)
  execute_process(COMMAND "${exe}" --list-test-cases --no-colors=true
    OUTPUT_VARIABLE out RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${exe} --list-test-cases failed (${rc}):\n${out}")
  endif()
  # Make the output safe to split into lines before looking at it.
  string(REPLACE ";" "<SEMICOLON>" out "${out}")
  string(REPLACE "[" "<LEFT-BRACKET>" out "${out}")
  string(REPLACE "]" "<RIGHT-BRACKET>" out "${out}")
  string(REPLACE "\\" "<BACKSLASH>" out "${out}")
  string(REPLACE "\n" ";" lines "${out}")
  get_filename_component(suite "${exe}" NAME)
  foreach(line IN LISTS lines)
    if(line MATCHES "^<LEFT-BRACKET>doctest<RIGHT-BRACKET>" OR line MATCHES "^=+$" OR line STREQUAL "")
      continue()
    endif()
    math(EXPR checked "${checked} + 1")
    if(line MATCHES "<SEMICOLON>|<LEFT-BRACKET>|<RIGHT-BRACKET>|<BACKSLASH>$|<BACKSLASH>(,|<BACKSLASH>)")
      string(APPEND bad_names "  ${suite}: ${line}\n")
    endif()
  endforeach()
endforeach()

if(bad_names)
  message(FATAL_ERROR "test-case names that ctest discovery would split or merge "
    "(rename them: no ';', '[' or ']', and no '\\' at the end or before ',' or '\\'):\n${bad_names}")
endif()
message(STATUS "${checked} test-case names checked, all safe for ctest discovery")
