# check_probes.cmake — the generated interfaces can catch drift, proved on probes (cmake -P).
#   -DFC=<Fortran compiler> -DMODDIR=<fricreg's .mod folder> -DGENERATOR=gen_interfaces.cmake
#   -DPROBES=<fortran/tests/probes> -DWORK=<scratch folder>
# 1. probe_ok.f90 compiles against module fricreg_c (so a failure below is not a set-up fault);
# 2. probe_arity.f90 (one argument too many) and probe_type.f90 (a default integer for a
#    size_t) do not, each with the compiler's message for that fault;
# 3. gen_interfaces.cmake refuses a header with a type it cannot spell (float), a variadic
#    prototype, and two parameters one in Fortran (W, w), naming them, instead of writing a
#    wrong interface.
foreach(var FC MODDIR GENERATOR PROBES WORK)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "check_probes.cmake: -D${var}=... is required")
  endif()
endforeach()
file(MAKE_DIRECTORY "${WORK}")
set(failures "")

function(compile_probe name out_result out_text)
  execute_process(COMMAND "${FC}" -c "-I${MODDIR}" "${PROBES}/${name}.f90" -o "${WORK}/${name}.o"
                  WORKING_DIRECTORY "${WORK}"
                  RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
  set(${out_result} "${result}" PARENT_SCOPE)
  set(${out_text} "${out}${err}" PARENT_SCOPE)
endfunction()

compile_probe(probe_ok result text)
if(NOT result EQUAL 0)
  list(APPEND failures "probe_ok.f90 does not compile: ${text}")
endif()
# expected: the compiler's words for the fault (gfortran's first; others' after the |).
set(expect_arity "More actual than formal arguments|[Tt]oo many arguments")
set(expect_type "Type mismatch in argument ...?m|type mismatch|does not match")
foreach(probe arity type)
  compile_probe(probe_${probe} result text)
  if(result EQUAL 0)
    list(APPEND failures "probe_${probe}.f90 compiled: the interfaces did not catch it")
  elseif(NOT text MATCHES "${expect_${probe}}")
    list(APPEND failures "probe_${probe}.f90 failed, but not for its fault: ${text}")
  else()
    message(STATUS "probe_${probe}.f90 rejected as it must be")
  endif()
endforeach()

set(expect_unknown_type "fricreg_probe_scale: parameter factor of type 'float' has no Fortran")
set(expect_variadic "fricreg_probe_printf is variadic")
set(expect_case "fricreg_probe_scale: two parameters named 'w' to Fortran")
foreach(probe unknown_type variadic case)
  execute_process(COMMAND "${CMAKE_COMMAND}" "-DHEADER=${PROBES}/probe_${probe}.h"
                          "-DOUT=${WORK}/probe_${probe}.inc" "-DPUBLIC_OUT=${WORK}/probe_pub.inc"
                          -P "${GENERATOR}"
                  RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
  string(REGEX REPLACE "[ \t\r\n]+" " " text "${out}${err}")
  if(result EQUAL 0)
    list(APPEND failures "gen_interfaces.cmake accepted probe_${probe}.h")
  elseif(NOT text MATCHES "${expect_${probe}}")
    list(APPEND failures "gen_interfaces.cmake failed on probe_${probe}.h, but not for its fault: ${text}")
  else()
    message(STATUS "probe_${probe}.h refused by the generator as it must be")
  endif()
endforeach()

if(failures)
  list(JOIN failures "\n" text)
  message(FATAL_ERROR "${text}")
endif()
message(STATUS "all 6 probes behave: the interfaces catch a wrong arity and a wrong type, and "
               "the generator refuses what it cannot spell")
