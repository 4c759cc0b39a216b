# Included by the top-level CMakeLists.txt before option(CMX_PYTHON): finds pybind11 and the
# python3 the module is built for, and sets CMX_PYTHON_DEFAULT (ON when both are usable).
#
# The interpreter: the one given as -DPYTHON_EXECUTABLE=... if any; else the first python3 on
# PATH that imports numpy, else /usr/bin/python3 (Debian's, where python3-numpy, python3-pytest
# and python3-meshio install), else the first python3 on PATH. It must have its C headers
# (Debian: python3-dev): without them pybind11's own search would stop the configuration, so
# pybind11 is not looked for and CMX_PYTHON defaults to OFF.
set(CMX_PYTHON_DEFAULT OFF)
if(NOT PYTHON_EXECUTABLE)
  find_program(cmx_python3_on_path python3 NO_CACHE)
  set(cmx_python3_candidates ${cmx_python3_on_path} /usr/bin/python3)
  set(cmx_python3_chosen "")
  foreach(candidate IN LISTS cmx_python3_candidates)
    if(EXISTS "${candidate}" AND NOT cmx_python3_chosen)
      execute_process(COMMAND "${candidate}" -c "import numpy" RESULT_VARIABLE cmx_numpy_rc OUTPUT_QUIET ERROR_QUIET)
      if(cmx_numpy_rc EQUAL 0)
        set(cmx_python3_chosen "${candidate}")
      endif()
    endif()
  endforeach()
  if(NOT cmx_python3_chosen AND cmx_python3_on_path)
    set(cmx_python3_chosen "${cmx_python3_on_path}")
  endif()
  if(cmx_python3_chosen)
    set(PYTHON_EXECUTABLE "${cmx_python3_chosen}" CACHE FILEPATH "python3 of the cmx Python module")
  endif()
endif()
if(PYTHON_EXECUTABLE)
  execute_process(COMMAND "${PYTHON_EXECUTABLE}" -c
      "import sysconfig, os; print(os.path.exists(os.path.join(sysconfig.get_paths()['include'], 'Python.h')))"
    OUTPUT_VARIABLE cmx_python_headers OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
  if(cmx_python_headers STREQUAL "True")
    find_package(pybind11 CONFIG QUIET)
    if(pybind11_FOUND)
      set(CMX_PYTHON_DEFAULT ON)
    endif()
  endif()
endif()
