# SPDX-License-Identifier: GPL-3.0-or-later
# gen_constants.cmake — the Fortran constants, generated from the C headers (cmake -P).
#
# Reads every `enum NAME { FRICREG_X = <integer>, ... };` of the headers given in HEADERS (a
# |-separated list: a CMake list would not survive the command line) and the version macros of
# VERSION_HEADER, and writes into OUT_DIR:
#   fricreg_constants.f90    module fricreg_constants: integer(c_int), parameter :: FRICREG_X
#   fricreg.fi               the same as PARAMETER statements, for INCLUDE in fixed-form F77
#   constants_check.c        test helper: the C compiler's value of each name, in order
#   constants_check.inc      test helper: the same names as the module's parameters, in order
#   constants_check_f77.f    test helper: the same names from fricreg.fi, in order
#   fricreg_constants_public.inc  `public :: <every name>`, for INCLUDE by the modules that
#                            re-export the constants under their explicit public lists
# An enumerator that is not `NAME = integer` (an implicit value, an expression, a macro) stops
# the build: the Fortran side must never silently miss or misread one. The test
# fortran_constants compiles the names into C and compares the values the C compiler gives
# them with the parsed ones, so a parse that went wrong in any other way fails there.
cmake_minimum_required(VERSION 3.18...3.25)
foreach(var OUT_DIR HEADERS VERSION_HEADER)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "gen_constants.cmake: -D${var}=... is required")
  endif()
endforeach()
string(REPLACE "|" ";" HEADERS "${HEADERS}")

set(names "")         # Fortran names
set(c_names "")       # the same constants' C names (equal, but for the version number)
set(values "")
set(functions "")     # every fricreg_* function declared, to catch a name clash
set(groups "")       # one entry per enum: "enum_name:first_index:count"
set(header_names "")

foreach(header IN LISTS HEADERS)
  file(READ "${header}" text)
  get_filename_component(header_name "${header}" NAME)
  list(APPEND header_names "${header_name}")
  # Strip comments (/* */ and //) and brackets and semicolons, which CMake lists mishandle.
  string(REGEX REPLACE "/\\*([^*]|\\*+[^*/])*\\*+/" " " text "${text}")
  string(REGEX REPLACE "//[^\n]*" " " text "${text}")
  string(REPLACE ";" " " text "${text}")
  string(REPLACE "[" " " text "${text}")
  string(REPLACE "]" " " text "${text}")
  string(REGEX MATCHALL "fricreg_[a-z0-9_]+[ \t\r\n]*\\(" calls "${text}")
  foreach(call IN LISTS calls)
    string(REGEX REPLACE "[ \t\r\n]*\\($" "" call "${call}")
    string(TOUPPER "${call}" call)
    list(APPEND functions "${call}")
  endforeach()
  string(REGEX MATCHALL "enum[ \t\r\n]+[A-Za-z_][A-Za-z0-9_]*[ \t\r\n]*{[^}]*}" enums "${text}")
  foreach(enum IN LISTS enums)
    string(REGEX MATCH "^enum[ \t\r\n]+([A-Za-z_][A-Za-z0-9_]*)" _ "${enum}")
    set(enum_name "${CMAKE_MATCH_1}")
    string(REGEX REPLACE "^[^{]*{([^}]*)}$" "\\1" body "${enum}")
    string(REPLACE "," ";" items "${body}")
    list(LENGTH names first)
    set(count 0)
    foreach(item IN LISTS items)
      string(STRIP "${item}" item)
      if(item STREQUAL "")
        continue() # trailing comma
      endif()
      if(NOT item MATCHES "^(FRICREG_[A-Z0-9_]+)[ \t\r\n]*=[ \t\r\n]*(-?[0-9]+)$")
        message(FATAL_ERROR "gen_constants.cmake: ${header_name}, enum ${enum_name}: cannot "
                            "read '${item}' (expected FRICREG_NAME = integer)")
      endif()
      set(name "${CMAKE_MATCH_1}")
      set(value "${CMAKE_MATCH_2}")
      string(LENGTH "${name}" len)
      if(len GREATER 31) # F77-style include files are read by fixed-form compilers
        message(FATAL_ERROR "gen_constants.cmake: ${name} is longer than 31 characters")
      endif()
      if(name IN_LIST names)
        message(FATAL_ERROR "gen_constants.cmake: ${name} is defined twice")
      endif()
      list(APPEND names "${name}")
      list(APPEND c_names "${name}")
      list(APPEND values "${value}")
      math(EXPR count "${count} + 1")
    endforeach()
    list(APPEND groups "${enum_name}:${first}:${count}")
  endforeach()
endforeach()

if(NOT names)
  message(FATAL_ERROR "gen_constants.cmake: no enum found in ${HEADERS}")
endif()

# Version macros: FRICREG_VERSION_MAJOR/MINOR/PATCH and the NUMBER they make.
file(READ "${VERSION_HEADER}" vtext)
foreach(part MAJOR MINOR PATCH)
  if(NOT vtext MATCHES "#define[ \t]+FRICREG_VERSION_${part}[ \t]+([0-9]+)")
    message(FATAL_ERROR "gen_constants.cmake: FRICREG_VERSION_${part} not found in ${VERSION_HEADER}")
  endif()
  set(version_${part} "${CMAKE_MATCH_1}")
endforeach()
math(EXPR version_number "${version_MAJOR} * 10000 + ${version_MINOR} * 100 + ${version_PATCH}")
list(LENGTH names n_enum)
list(APPEND groups "version macros:${n_enum}:4")
# FRICREG_VERSION_NUMBER would be the function fricreg_version_number to Fortran, which does
# not tell case: the headers' number is FRICREG_HEADER_VERSION (C: FRICREG_VERSION_NUMBER).
list(APPEND names FRICREG_VERSION_MAJOR FRICREG_VERSION_MINOR FRICREG_VERSION_PATCH
                  FRICREG_HEADER_VERSION)
list(APPEND c_names FRICREG_VERSION_MAJOR FRICREG_VERSION_MINOR FRICREG_VERSION_PATCH
                    FRICREG_VERSION_NUMBER)
list(APPEND values ${version_MAJOR} ${version_MINOR} ${version_PATCH} ${version_number})
list(LENGTH names n_all)
foreach(name IN LISTS names) # Fortran does not tell case: FRICREG_X and fricreg_x clash
  if(name IN_LIST functions)
    message(FATAL_ERROR "gen_constants.cmake: constant ${name} clashes with a function in Fortran")
  endif()
endforeach()
math(EXPR last "${n_all} - 1")
list(JOIN header_names ", " from)

# ---- module fricreg_constants, and fricreg.fi (the same, for INCLUDE by F77 callers) --------
# fricreg.fi: statements start in column 7 and end before column 73; comments start with '!'
# in column 1, which fixed-form (F90 and later, and gfortran -std=legacy) and free form both
# accept.
set(f90 "! Generated by fortran/gen_constants.cmake from ${from} and fricreg_version.h.\n")
string(APPEND f90 "! Do not edit: every value is the C header's, read at build time.\n")
string(APPEND f90 "module fricreg_constants\n  use, intrinsic :: iso_c_binding, only: c_int\n")
string(APPEND f90 "  implicit none\n  private\n")
set(fi "! fricreg.fi: fricreg's constants, for INCLUDE 'fricreg.fi'.\n")
string(APPEND fi "! Generated from ${from}: do not edit.\n")
string(APPEND fi "! The FR* entry points are listed in fortran/README.md.\n")
foreach(group IN LISTS groups)
  string(REPLACE ":" ";" g "${group}")
  list(GET g 0 gname)
  list(GET g 1 gfirst)
  list(GET g 2 gcount)
  string(APPEND f90 "\n  ! ${gname}\n")
  string(APPEND fi "! ${gname}\n")
  math(EXPR glast "${gfirst} + ${gcount} - 1")
  foreach(i RANGE ${gfirst} ${glast})
    list(GET names ${i} name)
    list(GET values ${i} value)
    string(APPEND f90 "  integer(c_int), parameter, public :: ${name} = ${value}\n")
    string(APPEND fi "      INTEGER ${name}\n      PARAMETER (${name} = ${value})\n")
  endforeach()
endforeach()
string(APPEND f90 "end module fricreg_constants\n")

# ---- fricreg_constants_public.inc: the names, for a module's explicit public list ----------
set(pub "! Generated by gen_constants.cmake: every constant, for INCLUDE in a public list.\n")
string(APPEND pub "  public :: &\n")
foreach(i RANGE ${last})
  list(GET names ${i} name)
  if(i EQUAL last)
    string(APPEND pub "    ${name}\n")
  else()
    string(APPEND pub "    ${name}, &\n")
  endif()
endforeach()

# ---- test helpers: the same names in C, in the module and in fricreg.fi ---------------------
set(c "/* Generated by gen_constants.cmake: the C compiler's value of each name, in order. */\n")
string(APPEND c "#include \"fricreg.h\"\n")
foreach(h IN LISTS header_names)
  if(NOT h STREQUAL "fricreg.h")
    string(APPEND c "#include \"${h}\"\n")
  endif()
endforeach()
string(APPEND c "\nint fricreg_check_count(void) { return ${n_all}; }\n\n")
string(APPEND c "int fricreg_check_c_value(int i) /* i = 1 ... count */\n{\n")
string(APPEND c "    static const int value[${n_all}] = {\n")
string(APPEND inc "! Generated by gen_constants.cmake: the module's value of each name, in order.\n")
string(APPEND inc "integer, parameter :: ncheck = ${n_all}\n")
string(APPEND inc "integer(c_int), parameter :: module_value(ncheck) = [ &\n")
set(inc_names "character(len=32), parameter :: check_name(ncheck) = [ character(len=32) :: &\n")
set(f77 "! Generated by gen_constants.cmake: fricreg.fi's values.\n")
string(APPEND f77 "      SUBROUTINE FRCHKF(V)\n      INCLUDE 'fricreg.fi'\n")
string(APPEND f77 "      INTEGER V(${n_all})\n")
foreach(i RANGE ${last})
  list(GET names ${i} name)
  list(GET c_names ${i} c_name)
  math(EXPR k "${i} + 1")
  set(sep ",")
  if(i EQUAL last)
    set(sep "")
  endif()
  string(APPEND c "        ${c_name}${sep}\n")
  string(APPEND inc "  ${name}${sep} &\n")
  string(APPEND inc_names "  '${name}'${sep} &\n")
  string(APPEND f77 "      V(${k}) = ${name}\n")
endforeach()
string(APPEND c "    };\n    return i >= 1 && i <= ${n_all} ? value[i - 1] : -1;\n}\n")
string(APPEND inc "]\n${inc_names}]\n")
string(APPEND f77 "      END\n")

include(${CMAKE_CURRENT_LIST_DIR}/write_if_changed.cmake)
file(MAKE_DIRECTORY "${OUT_DIR}")
write_if_changed("${OUT_DIR}/fricreg_constants.f90" "${f90}")
write_if_changed("${OUT_DIR}/fricreg.fi" "${fi}")
write_if_changed("${OUT_DIR}/constants_check.c" "${c}")
write_if_changed("${OUT_DIR}/constants_check.inc" "${inc}")
write_if_changed("${OUT_DIR}/constants_check_f77.f" "${f77}")
write_if_changed("${OUT_DIR}/fricreg_constants_public.inc" "${pub}")
