# SPDX-License-Identifier: GPL-3.0-or-later
# FindKLU.cmake — SuiteSparse's KLU, the sparse LU of the harmonic-balance driver's complex
# dynamic stiffnesses (Debian: libsuitesparse-dev, the package that brings CHOLMOD), which
# ships neither a CMake package nor a pkg-config file before SuiteSparse 6. Defines KLU_FOUND,
# KLU_INCLUDE_DIR, KLU_LIBRARY, KLU_VERSION and the imported target KLU::KLU (the shared
# library, which brings its own dependencies: AMD, COLAMD, BTF, SuiteSparse_config). Installed
# with fricreg's CMake package, as FindCHOLMOD.cmake.
find_path(KLU_INCLUDE_DIR NAMES klu.h PATH_SUFFIXES suitesparse)
find_library(KLU_LIBRARY NAMES klu)
if(KLU_INCLUDE_DIR AND EXISTS "${KLU_INCLUDE_DIR}/klu.h")
  file(STRINGS "${KLU_INCLUDE_DIR}/klu.h" KLU_VERSION_LINES
       REGEX "#define KLU_(MAIN|SUB)_VERSION")
  string(REGEX REPLACE ".*MAIN_VERSION ([0-9]+).*" "\\1" KLU_VERSION_MAJOR "${KLU_VERSION_LINES}")
  string(REGEX REPLACE ".*SUB_VERSION ([0-9]+).*" "\\1" KLU_VERSION_MINOR "${KLU_VERSION_LINES}")
  set(KLU_VERSION "${KLU_VERSION_MAJOR}.${KLU_VERSION_MINOR}")
endif()
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(KLU REQUIRED_VARS KLU_LIBRARY KLU_INCLUDE_DIR
                                  VERSION_VAR KLU_VERSION)
if(KLU_FOUND AND NOT TARGET KLU::KLU)
  add_library(KLU::KLU UNKNOWN IMPORTED)
  set_target_properties(KLU::KLU PROPERTIES IMPORTED_LOCATION "${KLU_LIBRARY}"
                        INTERFACE_INCLUDE_DIRECTORIES "${KLU_INCLUDE_DIR}")
endif()
mark_as_advanced(KLU_INCLUDE_DIR KLU_LIBRARY)
