# SPDX-License-Identifier: GPL-3.0-or-later
# FRICREG_PYTHON (AUTO, ON or OFF): the Python binding, python/. AUTO builds it where a
# Python 3 with its headers, cffi and numpy is found and says what is missing where not; ON
# makes that an error. The interpreter is the first of Python3_EXECUTABLE (if given), the one
# CMake's FindPython3 finds, and Debian's /usr/bin/python3 that imports cffi and numpy: a
# python3 earlier on PATH (pyenv, a virtualenv) may not see Debian's python3-cffi.
# It needs FRICREG_DRIVERS (harmonic balance and structures are drivers).
set(FRICREG_PYTHON AUTO CACHE STRING "Build the Python binding (AUTO, ON or OFF)")
set_property(CACHE FRICREG_PYTHON PROPERTY STRINGS AUTO ON OFF)
set(FRICREG_PYTHON_BUILT OFF)

function(fricreg_python_usable exe result)
  execute_process(COMMAND ${exe} -c "import cffi, numpy"
                  RESULT_VARIABLE rc OUTPUT_QUIET ERROR_QUIET)
  if(rc EQUAL 0)
    set(${result} ON PARENT_SCOPE)
  else()
    set(${result} OFF PARENT_SCOPE)
  endif()
endfunction()

if(NOT FRICREG_PYTHON STREQUAL "OFF" AND NOT FRICREG_DRIVERS)
  # the package wraps the drivers' harmonic balance and structures too
  set(missing "FRICREG_DRIVERS is OFF (the binding wraps harmonic balance and structures)")
  if(FRICREG_PYTHON STREQUAL "ON")
    message(FATAL_ERROR "FRICREG_PYTHON=ON, but ${missing}")
  endif()
  message(STATUS "Python binding not built: ${missing}")
elseif(NOT FRICREG_PYTHON STREQUAL "OFF")
  set(missing "")
  if(NOT DEFINED Python3_EXECUTABLE)
    find_package(Python3 3.7 COMPONENTS Interpreter QUIET)
    set(candidates ${Python3_EXECUTABLE} /usr/bin/python3)
    unset(Python3_EXECUTABLE)
    unset(Python3_EXECUTABLE CACHE)
    foreach(exe IN LISTS candidates)
      if(EXISTS ${exe})
        fricreg_python_usable(${exe} usable)
        if(usable)
          set(Python3_EXECUTABLE ${exe} CACHE FILEPATH "The Python of the binding")
          break()
        endif()
      endif()
    endforeach()
  endif()
  if(DEFINED Python3_EXECUTABLE)
    find_package(Python3 3.7 COMPONENTS Interpreter Development.Module QUIET)
    fricreg_python_usable(${Python3_EXECUTABLE} usable)
    if(NOT Python3_Development.Module_FOUND)
      set(missing "Python's headers are missing (Debian: python3-dev)")
    elseif(NOT usable)
      set(missing "${Python3_EXECUTABLE} lacks cffi or numpy (Debian: python3-cffi python3-numpy)")
    endif()
  else()
    set(missing "no Python 3 imports cffi and numpy (Debian: python3-cffi python3-numpy)")
  endif()
  if(missing STREQUAL "")
    set(FRICREG_PYTHON_EXECUTABLE ${Python3_EXECUTABLE})
    # The prefix's site-packages, relative to it (lib/python3.X/site-packages).
    execute_process(COMMAND ${FRICREG_PYTHON_EXECUTABLE} -c
      "import sysconfig; print(sysconfig.get_path('platlib', 'posix_prefix', vars={'base': '', 'platbase': ''}).lstrip('/'))"
      OUTPUT_VARIABLE site OUTPUT_STRIP_TRAILING_WHITESPACE)
    set(FRICREG_PYTHON_INSTALL_DIR ${site} CACHE STRING
        "Where cmake --install puts the Python package, relative to the prefix")
    add_subdirectory(python)
    set(FRICREG_PYTHON_BUILT ON)
    message(STATUS "Python binding: ${FRICREG_PYTHON_EXECUTABLE}, installed into "
                   "PREFIX/${FRICREG_PYTHON_INSTALL_DIR}")
  elseif(FRICREG_PYTHON STREQUAL "ON")
    message(FATAL_ERROR "FRICREG_PYTHON=ON, but ${missing}")
  else()
    message(STATUS "Python binding not built: ${missing}")
  endif()
endif()
