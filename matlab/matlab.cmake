# SPDX-License-Identifier: GPL-3.0-or-later
# MATLAB's build of the MEX gateway (included by matlab/CMakeLists.txt): FRICREG_MATLAB AUTO
# builds it where CMake's FindMatlab finds MATLAB with its MX library (and says what is missing
# where not), ON makes its absence an error, OFF skips it. The same sources as Octave's, built
# by matlab_add_mex with the R2017b API (separate complex: mxGetPr is a real array's data, as
# `mex -R2017b`), linked to libfricreg; fricreg_mex.mexa64 (MATLAB's extension for the
# platform) goes beside Octave's .mex and the .m files in the build folder, and is installed
# into FRICREG_OCTAVE_INSTALL_DIR with an rpath to the library relative to itself. Octave does
# not load MATLAB's binary, nor MATLAB Octave's, so one folder serves both. Not tested here:
# no MATLAB on the machines that build fricreg (docs/matlab.md).
if(FRICREG_MATLAB STREQUAL "OFF")
  return()
endif()
set(missing_matlab "")
if(NOT FRICREG_DRIVERS)
  set(missing_matlab "FRICREG_DRIVERS is OFF (the gateway wraps the identification fit, a driver)")
else()
  find_package(Matlab COMPONENTS MX_LIBRARY)
  if(NOT Matlab_FOUND OR NOT Matlab_MX_LIBRARY_FOUND)
    set(missing_matlab "MATLAB was not found by FindMatlab (set Matlab_ROOT_DIR to its installation, e.g. -DMatlab_ROOT_DIR=/usr/local/MATLAB/R2023b)")
  endif()
endif()
if(NOT missing_matlab STREQUAL "")
  if(FRICREG_MATLAB STREQUAL "ON")
    message(FATAL_ERROR "FRICREG_MATLAB=ON, but ${missing_matlab}")
  endif()
  message(STATUS "MATLAB MEX gateway not built: ${missing_matlab}")
  return()
endif()

matlab_add_mex(NAME fricreg_matlab SRC ${sources} OUTPUT_NAME fricreg_mex R2017b
               LINK_TO fricreg)
target_include_directories(fricreg_matlab PRIVATE ${PROJECT_SOURCE_DIR}/include
                                                  ${PROJECT_BINARY_DIR}/include)
target_compile_options(fricreg_matlab PRIVATE ${FRICREG_WARNINGS})
set_target_properties(fricreg_matlab PROPERTIES
  C_STANDARD 99 C_STANDARD_REQUIRED ON C_EXTENSIONS OFF
  LIBRARY_OUTPUT_DIRECTORY ${out} RUNTIME_OUTPUT_DIRECTORY ${out}
  BUILD_RPATH $<TARGET_FILE_DIR:fricreg>
  INSTALL_RPATH "$ORIGIN/${to_libdir}")
install(TARGETS fricreg_matlab LIBRARY DESTINATION ${FRICREG_OCTAVE_INSTALL_DIR}
                               RUNTIME DESTINATION ${FRICREG_OCTAVE_INSTALL_DIR})
foreach(file IN LISTS m_files)
  get_filename_component(name ${file} NAME)
  configure_file(${file} ${out}/${name} COPYONLY)
endforeach()
install(FILES ${m_files} DESTINATION ${FRICREG_OCTAVE_INSTALL_DIR})
set(FRICREG_MEX_M_INSTALLED ON)
message(STATUS "MATLAB MEX gateway: MATLAB ${Matlab_VERSION_STRING} at ${Matlab_ROOT_DIR}, "
               "installed into PREFIX/${FRICREG_OCTAVE_INSTALL_DIR}")
