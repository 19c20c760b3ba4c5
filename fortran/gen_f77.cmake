# SPDX-License-Identifier: GPL-3.0-or-later
# gen_f77.cmake — the mechanical F77 entry points, generated from a table (cmake -P).
#
#   cmake -DTABLE=fortran/fricreg_structure_f77.txt -DOUT=fricreg_structure_f77_generated.f90 \
#         -P gen_f77.cmake
#
# Most F77 entry points are one C call with each argument converted the same few ways; written
# by hand they were the same eight lines again, 144 times. The table gives each such wrapper in
# one line, its doc comment above it; this script writes the external subroutines. Wrappers
# with logic of their own (a refused count, a transposed scratch copy, strings, handles made
# or released) stay hand-written beside the table, in the .f90 of the same name.
#
# The table, line by line (blank lines and `#` lines are skipped):
#   use MODULE...              the modules every wrapper of the table uses (once, first)
#   !> text                    a doc comment line of the next wrapper, copied as it is
#   NAME CFUNC ARG:KIND...     a wrapper: subroutine NAME(ARG..., STAT) calling CFUNC(ARG...)
#     ARG:KIND...              (indented) more arguments of the wrapper above
# STAT is always last, INTEGER, intent(out): stat = int(CFUNC(...)), the C status. KIND is the
# F77 side of an argument and how it reaches C:
#   handle        INTEGER*8 H, intent(in)               fricreg_handle_to_ptr(h)
#   size          INTEGER, intent(in)                   int(x, c_size_t)
#   size0         INTEGER, intent(in)                   int(max(x, 0), c_size_t): a negative
#                   count reaches C as 0, a size it refuses, not as a huge one (the getters)
#   int           INTEGER, intent(in)                   int(x, c_int) clamped to +-huge(c_int):
#                   an ILP64 caller's value beyond an int reaches C as the nearest int (refused
#                   where C bounds it), not wrapped into range (2**32 + 5 would be 5)
#   double        DOUBLE PRECISION, intent(in)          as it is
#   double(*)     DOUBLE PRECISION array, intent(in)    as it is
#   double_out    DOUBLE PRECISION, intent(inout)       as it is (C writes it only on success,
#   double_out(*) DOUBLE PRECISION array, intent(inout)   so an output is inout, not out)
#   int64(*)      INTEGER*8 array, intent(in)           as it is (sparse index arrays)
#   int64_out     INTEGER*8, intent(inout)              as it is (a counter)
# An unknown kind, a wrapper without arguments or a name of more than six characters stops the
# build, naming the table's line.
cmake_minimum_required(VERSION 3.25)
foreach(var TABLE OUT)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "gen_f77.cmake: -D${var}=... is required")
  endif()
endforeach()
include(${CMAKE_CURRENT_LIST_DIR}/wrap_line.cmake)
include(${CMAKE_CURRENT_LIST_DIR}/write_if_changed.cmake)
get_filename_component(table_name "${TABLE}" NAME)

# The table's lines as a list: `;` and brackets (in the doc comments) would split it.
file(READ "${TABLE}" text)
string(REPLACE ";" "@SEMI@" text "${text}")
string(REPLACE "[" "@LB@" text "${text}")
string(REPLACE "]" "@RB@" text "${text}")
string(REPLACE "\n" ";" lines "${text}")

# f77_arg(NAME KIND DECL_VAR PASS_VAR): the declaration of one argument and what C is given.
function(f77_arg name kind decl_var pass_var)
  set(pass "${name}")
  if(kind STREQUAL "handle")
    set(decl "integer(c_int64_t), intent(in) :: ${name}")
    set(pass "fricreg_handle_to_ptr(${name})")
  elseif(kind STREQUAL "size")
    set(decl "integer, intent(in) :: ${name}")
    set(pass "int(${name}, c_size_t)")
  elseif(kind STREQUAL "size0")
    set(decl "integer, intent(in) :: ${name}")
    set(pass "int(max(${name}, 0), c_size_t)")
  elseif(kind STREQUAL "int")
    set(decl "integer, intent(in) :: ${name}")
    set(pass "int(min(max(${name}, -int(huge(0_c_int))), int(huge(0_c_int))), c_int)")
  elseif(kind STREQUAL "double")
    set(decl "double precision, intent(in) :: ${name}")
  elseif(kind STREQUAL "double(*)")
    set(decl "double precision, intent(in) :: ${name}(*)")
  elseif(kind STREQUAL "double_out")
    set(decl "double precision, intent(inout) :: ${name}")
  elseif(kind STREQUAL "double_out(*)")
    set(decl "double precision, intent(inout) :: ${name}(*)")
  elseif(kind STREQUAL "int64(*)")
    set(decl "integer(c_int64_t), intent(in) :: ${name}(*)")
  elseif(kind STREQUAL "int64_out")
    set(decl "integer(c_int64_t), intent(inout) :: ${name}")
  else()
    set(decl "")
  endif()
  set(${decl_var} "${decl}" PARENT_SCOPE)
  set(${pass_var} "${pass}" PARENT_SCOPE)
endfunction()

set(uses "")
set(body "")
set(doc "")
set(count 0)
set(current "") # the wrapper being read: its name, C function, arguments (name:kind)
set(lineno 0)
# Appends the wrapper in `current` (and its doc comment) to `body`.
macro(flush_wrapper)
  if(NOT current STREQUAL "")
    list(POP_FRONT current name cfunc)
    if(current STREQUAL "")
      message(FATAL_ERROR "gen_f77.cmake: ${table_name}: ${name} has no arguments")
    endif()
    set(names "")
    set(decls "")
    set(passes "")
    foreach(arg IN LISTS current)
      if(NOT arg MATCHES "^([a-z][a-z0-9_]*):(.+)$")
        message(FATAL_ERROR "gen_f77.cmake: ${table_name}: ${name}: cannot read '${arg}' "
                            "(NAME:KIND)")
      endif()
      f77_arg("${CMAKE_MATCH_1}" "${CMAKE_MATCH_2}" decl pass)
      if(decl STREQUAL "")
        message(FATAL_ERROR "gen_f77.cmake: ${table_name}: ${name}: argument ${CMAKE_MATCH_1} "
                            "has the unknown kind '${CMAKE_MATCH_2}'")
      endif()
      list(APPEND names "${CMAKE_MATCH_1}")
      string(APPEND decls "  ${decl}\n")
      list(APPEND passes "${pass}")
    endforeach()
    list(JOIN names ", " arglist)
    list(JOIN passes ", " passlist)
    wrap_line("subroutine ${name}(${arglist}, stat)" "              " "&" head)
    wrap_line("  stat = int(${cfunc}(${passlist}))" "         " "&" call)
    string(APPEND body "\n${doc}${head}${uses}  implicit none\n${decls}"
                       "  integer, intent(out) :: stat\n${call}end subroutine ${name}\n")
    math(EXPR count "${count} + 1")
    set(doc "")
    set(current "")
  endif()
endmacro()

foreach(line IN LISTS lines)
  math(EXPR lineno "${lineno} + 1")
  string(REPLACE "@SEMI@" ";" line "${line}") # back, for the doc comments only
  if(line MATCHES "^[ \t]*(#.*)?$")
    continue()
  elseif(line MATCHES "^use ([a-z0-9_ ]+)$")
    string(REGEX REPLACE " +" ";" modules "${CMAKE_MATCH_1}")
    foreach(module IN LISTS modules)
      string(APPEND uses "  use ${module}\n")
    endforeach()
  elseif(line MATCHES "^!>")
    flush_wrapper()
    string(REPLACE "@LB@" "[" line "${line}")
    string(REPLACE "@RB@" "]" line "${line}")
    string(APPEND doc "${line}\n")
  elseif(line MATCHES "^(fr[a-z0-9]*) +(fricreg_[a-z0-9_]+)( +.*)?$")
    set(next_name "${CMAKE_MATCH_1}") # flush_wrapper's own matches overwrite CMAKE_MATCH_*
    set(next_cfunc "${CMAKE_MATCH_2}")
    string(STRIP "${CMAKE_MATCH_3}" args)
    flush_wrapper()
    string(LENGTH "${next_name}" len)
    if(len GREATER 6)
      message(FATAL_ERROR "gen_f77.cmake: ${table_name}:${lineno}: ${next_name} has more "
                          "than six characters")
    endif()
    string(REGEX REPLACE " +" ";" args "${args}")
    set(current "${next_name};${next_cfunc};${args}")
  elseif(line MATCHES "^[ \t]+([^ \t].*)$" AND NOT current STREQUAL "")
    string(STRIP "${CMAKE_MATCH_1}" args)
    string(REGEX REPLACE "[ \t]+" ";" args "${args}")
    list(APPEND current ${args})
  else()
    message(FATAL_ERROR "gen_f77.cmake: ${table_name}:${lineno}: cannot read '${line}'")
  endif()
endforeach()
flush_wrapper()
if(count EQUAL 0)
  message(FATAL_ERROR "gen_f77.cmake: no wrapper in ${table_name}")
endif()
if(uses STREQUAL "")
  message(FATAL_ERROR "gen_f77.cmake: ${table_name} names no module (a `use` line)")
endif()

# Installed with the hand-written sources: the licence line comes along.
set(content "! SPDX-License-Identifier: GPL-3.0-or-later\n")
string(APPEND content "! Generated by fortran/gen_f77.cmake from fortran/${table_name}: do not edit.\n")
string(APPEND content "! ${count} F77 entry points, each one call of the C function it names.\n${body}")
write_if_changed("${OUT}" "${content}")
