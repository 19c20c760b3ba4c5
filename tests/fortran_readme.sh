#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# fortran/README.md and fortran/F77.md name every binding: each type-bound procedure of module fricreg (its
# types are in the object files fortran/*.F90 beside fricreg.F90, which re-exports them) in its
# type's rows of the table (those from the row that names the type in bold to the next bold
# row), as `name(` or `obj%name(`, and each named generic binding likewise; each name of the
# `public ::` lists of module fricreg (fricreg.F90: types, procedures, the iso_c_binding names
# it passes on); and each F77 entry
# point (fricreg_f77.f90, fricreg_sim_f77.f90,
# fricreg_joints_f77.f90, fricreg_structure_f77.f90, fricreg_hb_f77.f90, fricreg_f77_check.f90,
# fricreg_warnings_f77.f90, and the tables fortran/*_f77.txt whose wrappers gen_f77.cmake
# writes at build time)
# as `FRNAME(`, named once only across
# the files (external names share one space: a second definition would fail at link time, or
# silently take the first). One awk reads the README, the module and the F77 files: a grep per
# name took half a minute. Usage: fortran_readme.sh ROOT
root=$1
module=$root/fortran/fricreg.F90
[ -f "$root/fortran/README.md" ] && [ -f "$root/fortran/F77.md" ] && [ -f "$module" ] ||
    { echo "FAIL: no fortran/README.md, fortran/F77.md or $module"; exit 1; }
# The guide is README.md (the module) and F77.md (the module-free entry points), read as one.
readme=$(mktemp) && trap 'rm -f "$readme"' EXIT
cat "$root/fortran/README.md" "$root/fortran/F77.md" >"$readme"
# The object files of module fricreg, after fricreg.F90: every other .F90 of fortran/.
objects=
for f in "$root"/fortran/*.F90; do [ "$f" = "$module" ] || objects="$objects $f"; done
nmodule=$(($(echo "$objects" | wc -w) + 1))

# The F77 files, in this order; a missing one fails (awk is given those that exist).
f77_files="fricreg_f77.f90 fricreg_joints_f77.f90 fricreg_sim_f77.f90 fricreg_structure_f77.f90 fricreg_hb_f77.f90 fricreg_f77_check.f90 fricreg_warnings_f77.f90"
present= missing=
for f in $f77_files; do
    if [ -f "$root/fortran/$f" ]; then present="$present $root/fortran/$f"; else missing="$missing $f"; fi
done
# The tables of the generated entry points: a line `frname fricreg_function ARG:KIND...` each.
for f in "$root"/fortran/*_f77.txt; do [ -f "$f" ] && present="$present $f"; done
# shellcheck disable=SC2086 # the files are words
awk -v missing="$missing" -v nmodule="$nmodule" '
function fail(what) { fails_text = fails_text "FAIL: " what "\n"; fails++ }
FNR == 1 { nfile++ }
nfile == 1 { readme[++nreadme] = $0; next }
nfile <= 1 + nmodule {
    # "type procedure" for each public type-bound procedure (not `procedure, private`, nor the
    # `procedure, non_overridable` helpers of fricreg_object, public for the object files only)
    if ($0 ~ /^ *type(, *(abstract|extends\([a-z_]*\)))* *:: *fricreg_[a-z_]*/) t = $NF
    if ($0 ~ /^ *end type/) t = ""
    if (t != "" && $0 ~ /^ *procedure *::/) {
        n = $0; sub(/^ *procedure *:: */, "", n); sub(/[ =].*/, "", n)
        bound_type[++nbound] = t; bound_name[nbound] = n
    }
    # a named generic (set_matrix), its specifics `procedure, private`; not assignment(=)
    if (t != "" && $0 ~ /^ *generic *:: *[a-z_0-9]+ *=>/) {
        n = $0; sub(/^ *generic *:: */, "", n); sub(/[ =].*/, "", n)
        bound_type[++nbound] = t; bound_name[nbound] = n
    }
    # the names of the `public ::` lists of module fricreg, continued lines (&) too
    if (nfile == 2 && $0 ~ /public *::/) p = 1
    if (p) {
        line = $0; sub(/!.*/, "", line); sub(/.*public *:: */, "", line)
        p = (line ~ /&[ \t]*$/)
        k = split(line, parts, /[,& \t]+/)
        for (i = 1; i <= k; i++) if (parts[i] != "") public[++npublic] = parts[i]
    }
    next
}
{ # an F77 file: its entry points, upper case
    if ($0 ~ /^subroutine fr[a-z0-9]*\(/) {
        n = $0; sub(/^subroutine /, "", n); sub(/\(.*/, "", n)
        f77[++nf77] = toupper(n)
    }
    if (FILENAME ~ /\.txt$/ && $0 ~ /^fr[a-z0-9]* +fricreg_/) f77[++nf77] = toupper($1)
}
# The README names NAME as a regex on one of its lines (all lines, or the rows of a type).
function readme_has(re,    i) { for (i = 1; i <= nreadme; i++) if (readme[i] ~ re) return 1; return 0 }
function type_rows_have(t, name,    i, inside, any, line) {
    inside = 0; any = 0
    for (i = 1; i <= nreadme; i++) {
        line = readme[i]
        if (index(line, "| **") == 1) { inside = (index(line, "(" t ")") || index(line, "`" t "`")); continue }
        if (line !~ /^\|/) inside = 0
        if (!inside) continue
        any = 1
        if (index(line, "`" name "(") || index(line, "%" name "(")) return 1
    }
    return any ? 0 : -1
}
END {
    if (nbound == 0) fail("no type-bound procedures found in " ARGV[2] " and the object files")
    for (i = 1; i <= nbound; i++) {
        checked++
        r = type_rows_have(bound_type[i], bound_name[i])
        if (r < 0) fail(bound_type[i] " has no rows in the table of fortran/README.md")
        else if (r == 0) fail(bound_type[i] "%" bound_name[i] " is not in its type'\''s rows of fortran/README.md")
    }
    for (i = 1; i <= npublic; i++) {
        checked++
        if (!readme_has("`[a-z_(]*" public[i] "[`(]"))
            fail(public[i] " (public in module fricreg) is not in fortran/README.md")
    }
    k = split(missing, parts, " ")
    for (i = 1; i <= k; i++) fail("no fortran/" parts[i])
    if (nf77 == 0) fail("no F77 entry points found")
    for (i = 1; i <= nf77; i++) count[f77[i]]++
    # the names defined twice, in sorted order (a simple insertion sort: a few hundred names)
    for (name in count) if (count[name] > 1) twice[++ntwice] = name
    for (i = 2; i <= ntwice; i++) for (j = i; j > 1 && twice[j - 1] > twice[j]; j--) {
        tmp = twice[j]; twice[j] = twice[j - 1]; twice[j - 1] = tmp }
    for (i = 1; i <= ntwice; i++) fail("F77 entry point " twice[i] " is defined twice")
    for (i = 1; i <= nf77; i++) {
        checked++
        if (length(f77[i]) > 6) fail("F77 entry point " f77[i] " has more than six characters")
    }
    for (i = 1; i <= nf77; i++) {
        checked++
        if (!index_in_readme("`" f77[i] "(")) fail("F77 entry point " f77[i] " is not in fortran/README.md or F77.md")
    }
    printf "%s", fails_text
    printf "%d passed, %d failed\n", checked - fails, fails
    exit fails > 0
}
function index_in_readme(s,    i) { for (i = 1; i <= nreadme; i++) if (index(readme[i], s)) return 1; return 0 }
' "$readme" "$module" $objects $present
