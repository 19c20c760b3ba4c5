# SPDX-License-Identifier: GPL-3.0-or-later
# Writes fricreg-sim's man page: PROGRAM (a list: an emulator, if any, then fricreg-sim) run
# with --man, its output into OUTPUT; on failure no partial page is left for install to copy.
# Usage: cmake -DPROGRAM=... -DOUTPUT=... -P write_man.cmake
execute_process(COMMAND ${PROGRAM} --man OUTPUT_FILE ${OUTPUT}.tmp RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  file(REMOVE ${OUTPUT}.tmp)
  message(FATAL_ERROR "fricreg-sim --man failed: ${status}")
endif()
file(RENAME ${OUTPUT}.tmp ${OUTPUT})
