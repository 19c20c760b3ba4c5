# SPDX-License-Identifier: GPL-3.0-or-later
# libfricreg_petsc, the optional PETSc adapter (include/fricreg_petsc.h, src/petsc/): built when
# PETSc (pkg-config PETSc, Debian petsc-dev) and MPI are found, unless FRICREG_PETSC is OFF;
# FRICREG_PETSC=ON makes their absence an error. The core builds the same either way.
set(FRICREG_PETSC AUTO CACHE STRING "Build the PETSc adapter libfricreg_petsc: AUTO (when PETSc and MPI are found), ON, OFF")
set_property(CACHE FRICREG_PETSC PROPERTY STRINGS AUTO ON OFF)
set(FRICREG_PETSC_BUILT OFF)
if(NOT FRICREG_PETSC STREQUAL "OFF")
  find_package(PkgConfig QUIET)
  if(PKG_CONFIG_FOUND)
    pkg_check_modules(PETSC QUIET IMPORTED_TARGET PETSc)
  endif()
  # MPI only beside PETSc: a machine with MPI's runtime but not its headers (Octave pulls
  # Open MPI's libraries in) fails FindMPI's trial compile, which is an error even when QUIET
  if(PETSC_FOUND)
    find_package(MPI QUIET COMPONENTS C)
  endif()
  if(PETSC_FOUND AND MPI_C_FOUND)
    set(FRICREG_PETSC_BUILT ON)
  elseif(FRICREG_PETSC STREQUAL "ON")
    message(FATAL_ERROR "FRICREG_PETSC=ON but PETSc (pkg-config PETSc) or MPI was not found "
                        "(Debian: apt-get install petsc-dev)")
  else()
    message(STATUS "PETSc or MPI not found (Debian: petsc-dev): libfricreg_petsc and the MPI "
                   "examples are not built")
  endif()
endif()

# The MPI tests (label mpi: tests/petsc/, examples/petsc/) are registered only when
# FRICREG_PETSC=ON asks for the adapter: a plain ctest, the quick tier, does not start mpiexec
# because petsc-dev happens to be installed. The README's MPI command configures with
# -DFRICREG_PETSC=ON and runs them with ctest -L mpi.
set(FRICREG_MPI_TESTS OFF)
if(FRICREG_PETSC_BUILT AND FRICREG_PETSC STREQUAL "ON")
  set(FRICREG_MPI_TESTS ON)
endif()

if(FRICREG_PETSC_BUILT)
  if(FRICREG_MPI_TESTS)
    message(STATUS "PETSc ${PETSC_VERSION} and MPI found: building libfricreg_petsc and its MPI tests")
  else()
    message(STATUS "PETSc ${PETSC_VERSION} and MPI found: building libfricreg_petsc (its MPI "
                   "tests, label mpi, with -DFRICREG_PETSC=ON)")
  endif()
  set(FRICREG_PETSC_VERSION_SCRIPT ${PROJECT_SOURCE_DIR}/src/petsc/fricreg_petsc.map)
  # error.c: the core's message record, compiled in (hidden in libfricreg, as rk4_classic.c in
  # the problems).
  add_library(fricreg_petsc SHARED src/petsc/adapter.c src/petsc/coupling.c src/petsc/eval.c
                                   src/petsc/events.c src/petsc/jacobian.c src/petsc/options.c
                                   src/base/error.c)
  add_library(fricreg::fricreg_petsc ALIAS fricreg_petsc)
  target_include_directories(fricreg_petsc PUBLIC ${FRICREG_INCLUDE_DIRS}
                             PRIVATE ${PROJECT_SOURCE_DIR}/src)
  target_link_libraries(fricreg_petsc PUBLIC fricreg PkgConfig::PETSC MPI::MPI_C PRIVATE m)
  target_compile_options(fricreg_petsc PRIVATE ${FRICREG_WARNINGS})
  if(FRICREG_LD_VERSION_SCRIPT)
    target_link_options(fricreg_petsc PRIVATE
                        "LINKER:--version-script=${FRICREG_PETSC_VERSION_SCRIPT}")
  endif()
  # Installed next to libfricreg (both in CMAKE_INSTALL_LIBDIR), it finds it by RUNPATH $ORIGIN:
  # a consumer whose own RUNPATH names only the adapter's directory (a RUNPATH is not
  # inherited by the libraries it loads) starts without LD_LIBRARY_PATH, in any prefix
  # (tests/install_petsc.sh).
  set_target_properties(fricreg_petsc PROPERTIES
    VERSION ${PROJECT_VERSION}
    SOVERSION ${FRICREG_PETSC_SOVERSION}
    C_VISIBILITY_PRESET hidden
    INSTALL_RPATH "$ORIGIN"
    LINK_DEPENDS ${FRICREG_PETSC_VERSION_SCRIPT})
  # Installed with its own export set: its link interface names PkgConfig::PETSC and
  # MPI::MPI_C, which only a consumer that asks for the component (find_package(fricreg
  # COMPONENTS petsc), fricregConfig.cmake) recreates. fricreg_petsc.pc for pkg-config.
  set_target_properties(fricreg_petsc PROPERTIES EXPORT_NAME fricreg_petsc)
  install(TARGETS fricreg_petsc EXPORT fricregPetscTargets
          LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
  install(FILES include/fricreg_petsc.h DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
  install(EXPORT fricregPetscTargets NAMESPACE fricreg::
          DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/fricreg)
  file(RELATIVE_PATH FRICREG_PC_TO_PREFIX "/${CMAKE_INSTALL_LIBDIR}/pkgconfig" "/")
  configure_file(${PROJECT_SOURCE_DIR}/cmake/fricreg_petsc.pc.in
                 ${PROJECT_BINARY_DIR}/fricreg_petsc.pc @ONLY)
  install(FILES ${PROJECT_BINARY_DIR}/fricreg_petsc.pc
          DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
endif()

# fricreg_mpi_test_properties(TEST RANKS TIMEOUT): label mpi, and the environment mpiexec
# needs here: Open MPI refuses root unless told (CI runs as root), a 2-rank run on a machine
# that reports fewer free slots needs oversubscription, and a rank that waits yields its core
# (mpi_yield_when_idle) rather than spin, which on a machine shared with other jobs makes two
# ranks slower than one (docs/distributed.md, "Scaling on this machine").
function(fricreg_mpi_test_properties test ranks timeout)
  set_tests_properties(${test} PROPERTIES LABELS mpi TIMEOUT ${timeout} PROCESSORS ${ranks}
    ENVIRONMENT "OMPI_ALLOW_RUN_AS_ROOT=1;OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1;OMPI_MCA_rmaps_base_oversubscribe=1;OMPI_MCA_mpi_yield_when_idle=1")
endfunction()

# fricreg_add_mpi_test(NAME RANKS TIMEOUT PROGRAM ARGS...): the test NAME_npRANKS, PROGRAM run
# by mpiexec on RANKS ranks.
function(fricreg_add_mpi_test name ranks timeout)
  add_test(NAME ${name}_np${ranks}
           COMMAND ${MPIEXEC_EXECUTABLE} ${MPIEXEC_NUMPROC_FLAG} ${ranks} ${MPIEXEC_PREFLAGS}
                   ${ARGN} ${MPIEXEC_POSTFLAGS})
  fricreg_mpi_test_properties(${name}_np${ranks} ${ranks} ${timeout})
endfunction()
