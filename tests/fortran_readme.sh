#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# fortran/README.md names every binding: each type-bound procedure of module fricreg
# (fricreg.F90) in its type's rows of the table (those from the row that names the type in bold
# to the next bold row), as `name(` or `obj%name(`; each name of the module's `public ::`
# lists (types, procedures, the iso_c_binding names it passes on); and each F77 entry point (fricreg_f77.f90, fricreg_sim_f77.f90,
# fricreg_joints_f77.f90, fricreg_structure_f77.f90, fricreg_hb_f77.f90, fricreg_f77_check.f90)
# as `FRNAME(`, named once only across
# the files (external names share one space: a second definition would fail at link time, or
# silently take the first). Usage: fortran_readme.sh ROOT
root=$1
readme=$root/fortran/README.md module=$root/fortran/fricreg.F90
fails=0 checked=0
fail() { echo "FAIL: $*"; fails=$((fails + 1)); }
[ -f "$readme" ] && [ -f "$module" ] || { echo "FAIL: no $readme or $module"; exit 1; }

# "type procedure" for each public type-bound procedure (not `procedure, private`).
bound=$(awk '/^ *type(, *(abstract|extends\([a-z_]*\)))* *:: *fricreg_[a-z_]*/ { t = $NF }
             /^ *end type/ { t = "" }
             t != "" && /^ *procedure *::/ { n = $0; sub(/^ *procedure *:: */, "", n)
                                             sub(/[ =].*/, "", n); print t, n }' "$module")
[ -n "$bound" ] || fail "no type-bound procedures found in $module"
echo "$bound" | while read -r type name; do
    [ -n "$type" ] || continue
    # The type's rows: from the bold row naming `type(T)` or `T` to the next bold row.
    rows=$(awk -v t="$type" 'index($0, "| **") == 1 { inside = (index($0, "(" t ")") || index($0, "`" t "`")); next }
                             !/^\|/ { inside = 0 } inside' "$readme")
    if [ -z "$rows" ]; then
        echo "FAIL: $type has no rows in the table of fortran/README.md"
    elif ! printf '%s\n' "$rows" | grep -q "[\`%]$name("; then
        echo "FAIL: $type%$name is not in its type's rows of fortran/README.md"
    else
        echo "ok"
    fi
done >"${TMPDIR:-/tmp}/fortran_readme.$$"
checked=$((checked + $(grep -c . "${TMPDIR:-/tmp}/fortran_readme.$$")))
fails=$((fails + $(grep -c '^FAIL' "${TMPDIR:-/tmp}/fortran_readme.$$")))
grep '^FAIL' "${TMPDIR:-/tmp}/fortran_readme.$$"
rm -f "${TMPDIR:-/tmp}/fortran_readme.$$"

# The module's public names, its `public ::` lists (the generated ones are the C functions').
public=$(awk '/public *::/ { p = 1 }
              p { line = $0; sub(/!.*/, "", line); sub(/.*public *:: */, "", line); print line
                  p = (line ~ /&[ \t]*$/) }' "$module" | tr ',&' '\n\n' | tr -d ' ' | grep .)
for name in $public; do
    checked=$((checked + 1))
    grep -q "\`[a-z_(]*$name[\`(]" "$readme" || fail "$name (public in module fricreg) is not in fortran/README.md"
done

# The F77 entry points.
f77_files="fricreg_f77.f90 fricreg_joints_f77.f90 fricreg_sim_f77.f90 fricreg_structure_f77.f90 fricreg_hb_f77.f90 fricreg_f77_check.f90"
for f in $f77_files; do
    [ -f "$root/fortran/$f" ] || fail "no fortran/$f"
done
for f in $f77_files; do
    sed -n 's/^subroutine \(fr[a-z0-9]*\)(.*/\1/p' "$root/fortran/$f"
done | tr 'a-z' 'A-Z' >"${TMPDIR:-/tmp}/fortran_f77.$$"
[ -s "${TMPDIR:-/tmp}/fortran_f77.$$" ] || fail "no F77 entry points found"
for name in $(sort "${TMPDIR:-/tmp}/fortran_f77.$$" | uniq -d); do
    fail "F77 entry point $name is defined twice"
done
while read -r name; do
    checked=$((checked + 1))
    [ ${#name} -le 6 ] || fail "F77 entry point $name has more than six characters"
done <"${TMPDIR:-/tmp}/fortran_f77.$$"
while read -r name; do
    checked=$((checked + 1))
    grep -q "\`$name(" "$readme" || fail "F77 entry point $name is not in fortran/README.md"
done <"${TMPDIR:-/tmp}/fortran_f77.$$"
rm -f "${TMPDIR:-/tmp}/fortran_f77.$$"
echo "$((checked - fails)) passed, $fails failed"
[ $fails -eq 0 ]
