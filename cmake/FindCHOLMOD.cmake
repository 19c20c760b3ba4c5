# SPDX-License-Identifier: GPL-3.0-or-later
# FindCHOLMOD.cmake — SuiteSparse's CHOLMOD (Debian: libsuitesparse-dev), which ships neither
# a CMake package nor a pkg-config file before SuiteSparse 6. Defines CHOLMOD_FOUND,
# CHOLMOD_INCLUDE_DIR, CHOLMOD_LIBRARY, CHOLMOD_VERSION and the imported target
# CHOLMOD::CHOLMOD (the shared library, which brings its own dependencies: AMD, COLAMD, CAMD,
# METIS, BLAS, LAPACK, SuiteSparse_config). Installed with fricreg's CMake package, whose
# static library's users find it through find_dependency(CHOLMOD).
find_path(CHOLMOD_INCLUDE_DIR NAMES cholmod.h PATH_SUFFIXES suitesparse)
find_library(CHOLMOD_LIBRARY NAMES cholmod)
if(CHOLMOD_INCLUDE_DIR AND EXISTS "${CHOLMOD_INCLUDE_DIR}/cholmod_core.h")
  file(STRINGS "${CHOLMOD_INCLUDE_DIR}/cholmod_core.h" CHOLMOD_VERSION_LINES
       REGEX "#define CHOLMOD_(MAIN|SUB|SUBSUB)_VERSION")
  string(REGEX REPLACE ".*MAIN_VERSION ([0-9]+).*" "\\1" CHOLMOD_VERSION_MAJOR
         "${CHOLMOD_VERSION_LINES}")
  string(REGEX REPLACE ".*SUB_VERSION ([0-9]+).*" "\\1" CHOLMOD_VERSION_MINOR
         "${CHOLMOD_VERSION_LINES}")
  set(CHOLMOD_VERSION "${CHOLMOD_VERSION_MAJOR}.${CHOLMOD_VERSION_MINOR}")
endif()
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(CHOLMOD REQUIRED_VARS CHOLMOD_LIBRARY CHOLMOD_INCLUDE_DIR
                                  VERSION_VAR CHOLMOD_VERSION)
if(CHOLMOD_FOUND AND NOT TARGET CHOLMOD::CHOLMOD)
  add_library(CHOLMOD::CHOLMOD UNKNOWN IMPORTED)
  set_target_properties(CHOLMOD::CHOLMOD PROPERTIES IMPORTED_LOCATION "${CHOLMOD_LIBRARY}"
                        INTERFACE_INCLUDE_DIRECTORIES "${CHOLMOD_INCLUDE_DIR}")
endif()
mark_as_advanced(CHOLMOD_INCLUDE_DIR CHOLMOD_LIBRARY)
