# The Python module (python/): built when an interpreter with NumPy, its headers and pybind11
# are found (Debian: python3-dev, python3-numpy, pybind11-dev), unless SINEW_BUILD_PYTHON=OFF.
# The interpreter is the first of `python3` on PATH and /usr/bin/python3 that imports NumPy
# (a pyenv or venv python3 without NumPy comes first on some PATHs); set Python3_EXECUTABLE
# to choose another.
if(NOT DEFINED Python3_EXECUTABLE)
  foreach(candidate python3 /usr/bin/python3)
    execute_process(COMMAND ${candidate} -c "import numpy, sys; print(sys.executable)"
      OUTPUT_VARIABLE executable RESULT_VARIABLE status ERROR_QUIET
      OUTPUT_STRIP_TRAILING_WHITESPACE)
    if(status EQUAL 0 AND EXISTS "${executable}")
      set(Python3_EXECUTABLE "${executable}" CACHE FILEPATH "The Python interpreter of the module")
      break()
    endif()
  endforeach()
endif()
find_package(Python3 3.8 COMPONENTS Interpreter Development.Module NumPy QUIET)
if(Python3_FOUND)
  find_package(pybind11 2.6 CONFIG QUIET)
endif()
if(Python3_FOUND AND pybind11_FOUND)
  set(python_default ON)
else()
  set(python_default OFF)
endif()
option(SINEW_BUILD_PYTHON "Build the Python module (needs Python 3 with NumPy, pybind11)"
  ${python_default})
if(SINEW_BUILD_PYTHON)
  if(NOT Python3_FOUND OR NOT pybind11_FOUND)
    message(FATAL_ERROR "SINEW_BUILD_PYTHON is ON but Python 3 with NumPy and its headers, or "
      "pybind11, was not found (scripts/setup.sh installs them)")
  endif()
  message(STATUS "Python module: ${Python3_EXECUTABLE} (Python ${Python3_VERSION}), "
    "pybind11 ${pybind11_VERSION}")
  add_subdirectory(python)
else()
  message(STATUS "Python module: not built (SINEW_BUILD_PYTHON=OFF)")
endif()
