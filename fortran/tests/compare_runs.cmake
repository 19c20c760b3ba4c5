# SPDX-License-Identifier: GPL-3.0-or-later
# compare_runs.cmake — run two programs and require the same output, byte for byte (cmake -P).
#
# -DA=program -DB=program: both must exit 0 and print the same stdout. The F77 tests print
# their numbers with 17 significant digits, which tell every double apart, so equal output
# means the same numbers bit for bit (fortran_*_ilp64: the default build against the build
# with an 8-byte default INTEGER).
foreach(var A B)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "compare_runs.cmake: -D${var}=... is required")
  endif()
endforeach()
foreach(var A B)
  execute_process(COMMAND ${${var}} RESULT_VARIABLE rc OUTPUT_VARIABLE out_${var}
                  ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${${var}} exited with ${rc}:\n${out_${var}}${err}")
  endif()
endforeach()
if(NOT out_A STREQUAL out_B)
  message(FATAL_ERROR "the outputs differ\n--- ${A}\n${out_A}--- ${B}\n${out_B}")
endif()
string(REGEX MATCHALL "E[-+][0-9][0-9]" numbers "${out_A}")
list(LENGTH numbers n)
if(n EQUAL 0)
  message(FATAL_ERROR "no number with an exponent in the output: nothing was compared")
endif()
message(STATUS "${n} numbers, the same bit for bit:\n${out_A}")
