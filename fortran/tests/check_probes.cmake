# SPDX-License-Identifier: GPL-3.0-or-later
# check_probes.cmake — the generated interfaces can catch drift, proved on probes (cmake -P).
#   -DFC=<Fortran compiler> -DMODDIR=<fricreg's .mod folder> -DGENERATOR=gen_interfaces.cmake
#   -DPROBES=<fortran/tests/probes> -DWORK=<scratch folder>
# 1. probe_ok.f90 compiles against module fricreg_c (so a failure below is not a set-up fault),
#    and probe_public.f90, which names what the README says `use fricreg` gives;
# 2. probe_arity.f90 (one argument too many) and probe_type.f90 (a default integer for a
#    size_t) do not, each with the compiler's message for that fault, nor probe_private.f90,
#    which names an internal helper of module fricreg;
# 3. gen_interfaces.cmake refuses a header with a type it cannot spell (float), a variadic
#    prototype, and two parameters one in Fortran (W, w), naming them, instead of writing a
#    wrong interface.
cmake_minimum_required(VERSION 3.25)
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

foreach(probe probe_ok probe_public)
  compile_probe(${probe} result text)
  if(NOT result EQUAL 0)
    list(APPEND failures "${probe}.f90 does not compile: ${text}")
  endif()
endforeach()
# expect_refused(PROBE RESULT TEXT EXPECTED): PROBE must have failed (RESULT nonzero) with a
# message matching EXPECTED, else a line in `failures`.
function(expect_refused probe result text expected)
  string(REGEX REPLACE "[ \t\r\n]+" " " text "${text}")
  if(result EQUAL 0)
    list(APPEND failures "${probe} was accepted: the check cannot catch its fault")
  elseif(NOT text MATCHES "${expected}")
    list(APPEND failures "${probe} was refused, but not for its fault: ${text}")
  else()
    message(STATUS "${probe} refused as it must be")
  endif()
  set(failures "${failures}" PARENT_SCOPE)
endfunction()

# The compiler's words for each fault (gfortran's first; others' after the |).
compile_probe(probe_arity result text)
expect_refused(probe_arity.f90 "${result}" "${text}"
               "More actual than formal arguments|[Tt]oo many arguments")
compile_probe(probe_type result text)
expect_refused(probe_type.f90 "${result}" "${text}"
               "Type mismatch in argument ...?m|type mismatch|does not match")
compile_probe(probe_private result text)
expect_refused(probe_private.f90 "${result}" "${text}"
               "error_record.* not found in module|is PRIVATE|not a public entity|private")

# The generator's own messages.
set(expect_unknown_type "fricreg_probe_scale: parameter factor of type 'float' has no Fortran")
set(expect_variadic "fricreg_probe_printf is variadic")
set(expect_case "fricreg_probe_scale: two parameters named 'w' to Fortran")
foreach(probe unknown_type variadic case)
  execute_process(COMMAND "${CMAKE_COMMAND}" "-DHEADERS=${PROBES}/probe_${probe}.h"
                          "-DOUT=${WORK}/probe_${probe}.inc" "-DPUBLIC_OUT=${WORK}/probe_pub.inc"
                          -P "${GENERATOR}"
                  RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
  expect_refused(probe_${probe}.h "${result}" "${out}${err}" "${expect_${probe}}")
endforeach()

if(failures)
  list(JOIN failures "\n" text)
  message(FATAL_ERROR "${text}")
endif()
message(STATUS "all 8 probes behave: the interfaces catch a wrong arity and a wrong type, "
               "module fricreg gives its public names only, and the generator refuses what it "
               "cannot spell")
