# SPDX-License-Identifier: GPL-3.0-or-later
# check_bindings.cmake — every function the library exports has a Fortran bind(C) interface
# (cmake -P; -DHEADERS=a.h|b.h -DSOURCES=a.f90|b.inc).
#
# The interfaces are generated from the public headers of include/, so they match the
# prototypes by construction; what can still go wrong is a public header (or a function) that
# never reaches the generator. HEADERS is every installed public header, SOURCES the thin-layer
# modules and the generated interface files: a FRICREG_API function of any public header with
# no `bind(C, name='...')` fails here, naming it. The generator's own mapping is checked by
# check_probes.cmake (wrong arity, wrong type, an unknown C type).
string(REPLACE "|" ";" HEADERS "${HEADERS}")
string(REPLACE "|" ";" SOURCES "${SOURCES}")
set(fortran "")
foreach(source IN LISTS SOURCES)
  file(READ "${source}" text)
  string(APPEND fortran "${text}")
endforeach()
set(missing "")
set(count 0)
foreach(header IN LISTS HEADERS)
  file(READ "${header}" text)
  string(REGEX MATCHALL "FRICREG_API[^;(]*[ *]fricreg_[a-z0-9_]+[ \t]*\\(" decls "${text}")
  foreach(decl IN LISTS decls)
    # the last fricreg_ name: a result type may be one too (const fricreg_element_type *)
    string(REGEX MATCH "fricreg_[a-z0-9_]+[ \t]*\\($" name "${decl}")
    string(REGEX MATCH "fricreg_[a-z0-9_]+" name "${name}")
    math(EXPR count "${count} + 1")
    if(NOT fortran MATCHES "bind\\(C, name='${name}'\\)")
      list(APPEND missing "${name}")
    endif()
  endforeach()
endforeach()
if(count EQUAL 0)
  message(FATAL_ERROR "no FRICREG_API declaration found in ${HEADERS}")
endif()
if(missing)
  message(FATAL_ERROR "C functions with no Fortran bind(C) interface: ${missing} "
                      "(are their headers under include/ in the top-level FRICREG_PUBLIC_HEADERS?)")
endif()
message(STATUS "all ${count} public C functions have a Fortran bind(C) interface")
