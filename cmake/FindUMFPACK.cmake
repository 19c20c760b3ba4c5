# SPDX-License-Identifier: GPL-3.0-or-later
# FindUMFPACK.cmake — SuiteSparse's UMFPACK, the sparse LU of the harmonic-balance driver's
# complex dynamic stiffnesses (Debian: libsuitesparse-dev, the package that brings CHOLMOD),
# which ships neither a CMake package nor a pkg-config file before SuiteSparse 6. Defines
# UMFPACK_FOUND, UMFPACK_INCLUDE_DIR, UMFPACK_LIBRARY, UMFPACK_VERSION and the imported target
# UMFPACK::UMFPACK (the shared library, which brings its own dependencies: AMD, CHOLMOD, BLAS,
# SuiteSparse_config). Installed with fricreg's CMake package, as FindCHOLMOD.cmake.
find_path(UMFPACK_INCLUDE_DIR NAMES umfpack.h PATH_SUFFIXES suitesparse)
find_library(UMFPACK_LIBRARY NAMES umfpack)
if(UMFPACK_INCLUDE_DIR AND EXISTS "${UMFPACK_INCLUDE_DIR}/umfpack.h")
  file(STRINGS "${UMFPACK_INCLUDE_DIR}/umfpack.h" UMFPACK_VERSION_LINES
       REGEX "#define UMFPACK_(MAIN|SUB)_VERSION")
  string(REGEX REPLACE ".*MAIN_VERSION ([0-9]+).*" "\\1" UMFPACK_VERSION_MAJOR
         "${UMFPACK_VERSION_LINES}")
  string(REGEX REPLACE ".*SUB_VERSION ([0-9]+).*" "\\1" UMFPACK_VERSION_MINOR
         "${UMFPACK_VERSION_LINES}")
  set(UMFPACK_VERSION "${UMFPACK_VERSION_MAJOR}.${UMFPACK_VERSION_MINOR}")
endif()
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(UMFPACK REQUIRED_VARS UMFPACK_LIBRARY UMFPACK_INCLUDE_DIR
                                  VERSION_VAR UMFPACK_VERSION)
if(UMFPACK_FOUND AND NOT TARGET UMFPACK::UMFPACK)
  add_library(UMFPACK::UMFPACK UNKNOWN IMPORTED)
  set_target_properties(UMFPACK::UMFPACK PROPERTIES IMPORTED_LOCATION "${UMFPACK_LIBRARY}"
                        INTERFACE_INCLUDE_DIRECTORIES "${UMFPACK_INCLUDE_DIR}")
endif()
mark_as_advanced(UMFPACK_INCLUDE_DIR UMFPACK_LIBRARY)
