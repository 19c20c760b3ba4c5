# SPDX-License-Identifier: GPL-3.0-or-later
# write_if_changed(PATH CONTENT): write CONTENT to PATH only if it differs, so that a header
# whose generated Fortran is unchanged does not rebuild the Fortran sources (used by the
# generators gen_constants.cmake and gen_interfaces.cmake).
function(write_if_changed path content)
  if(EXISTS "${path}")
    file(READ "${path}" old)
    if(old STREQUAL content)
      return()
    endif()
  endif()
  file(WRITE "${path}" "${content}")
endfunction()
