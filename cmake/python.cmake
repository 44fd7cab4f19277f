# RECODE_BUILD_PYTHON: the Python module `recode` (python/, pybind11). Default: ON where pybind11
# and a Python 3 interpreter that imports NumPy (the module's arrays) are found, except with
# RECODE_LIBRARY_ONLY, where it is OFF unless asked for. Asking for it without them is an error.
#
# The interpreter: Python_EXECUTABLE if given (-DPython_EXECUTABLE=/path/to/python3), else the
# first of `python3` on PATH and /usr/bin/python3 that imports NumPy. A pyenv or venv python3
# earlier on PATH without NumPy would otherwise be chosen, and the module built for it.
function(recode_pick_python_interpreter)
  if(Python_EXECUTABLE)
    return()
  endif()
  find_program(recode_path_python3 NAMES python3 NO_CACHE)
  foreach(candidate ${recode_path_python3} /usr/bin/python3)
    if(EXISTS "${candidate}")
      execute_process(COMMAND "${candidate}" -c "import numpy" RESULT_VARIABLE failed
                      OUTPUT_QUIET ERROR_QUIET)
      if(NOT failed)
        set(Python_EXECUTABLE "${candidate}" CACHE FILEPATH "Python for the recode module")
        return()
      endif()
    endif()
  endforeach()
endfunction()

set(recode_python_missing "")
if(NOT DEFINED RECODE_BUILD_PYTHON OR RECODE_BUILD_PYTHON)
  recode_pick_python_interpreter()
  find_package(Python 3.8 QUIET COMPONENTS Interpreter Development.Module)
  if(Python_FOUND)
    execute_process(COMMAND "${Python_EXECUTABLE}" -c "import numpy" RESULT_VARIABLE no_numpy
                    OUTPUT_QUIET ERROR_QUIET)
    if(no_numpy)
      string(APPEND recode_python_missing " NumPy for ${Python_EXECUTABLE} (python3-numpy)")
    endif()
    find_package(pybind11 2.6 CONFIG QUIET)
    if(NOT pybind11_FOUND)
      string(APPEND recode_python_missing " pybind11 (pybind11-dev)")
    endif()
  else()
    string(APPEND recode_python_missing " Python 3 with its headers (python3-dev)")
  endif()
endif()

if(recode_python_missing STREQUAL "" AND NOT RECODE_LIBRARY_ONLY)
  set(recode_python_default ON)
else()
  set(recode_python_default OFF)
endif()
option(RECODE_BUILD_PYTHON "Build the Python module recode (python/, pybind11)"
       ${recode_python_default})
if(RECODE_BUILD_PYTHON AND NOT recode_python_missing STREQUAL "")
  message(FATAL_ERROR "RECODE_BUILD_PYTHON is ON but these are missing:${recode_python_missing}")
endif()
if(RECODE_BUILD_PYTHON)
  message(STATUS "recode: Python module for ${Python_EXECUTABLE} (Python ${Python_VERSION})")
  set(RECODE_PYTHON_MODULE_DIR ${PROJECT_BINARY_DIR}/python)
elseif(NOT recode_python_missing STREQUAL "")
  message(STATUS "recode: no Python module; missing:${recode_python_missing}")
endif()
