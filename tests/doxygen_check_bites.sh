#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The API reference check can fail: on copies of the headers with one fault each, rendered by
# the same Doxyfile with only the headers as input, it must fail and name the fault; the
# unbroken copy passes, so the failures are the faults'. Exits 77 (skipped) without Doxygen.
# Usage: doxygen_check_bites.sh CHECK DOXYGEN|- DOXYFILE INCLUDE_DIR VERSION_HEADER
check=$1 doxygen=$2 doxyfile=$3 include=$4 version=$5
if [ "$doxygen" = "-" ] || ! command -v "$doxygen" >/dev/null 2>&1; then
    echo "Doxygen not found: the API reference check's probes are skipped"
    exit 77
fi
work=$(mktemp -d "${TMPDIR:-/tmp}/fricreg-doxygen-bites.XXXXXX")
trap 'rm -rf "$work"' EXIT
{ cat "$doxyfile"; printf 'INPUT = %s %s\nUSE_MDFILE_AS_MAINPAGE =\n' "$work/h" "$version"; } \
    >"$work/Doxyfile"
fails=0 passes=0
probe() { # NAME HEADER SED_SCRIPT EXPECTED: breaks HEADER's copy, expects EXPECTED in the failure
    rm -rf "$work/h" && mkdir "$work/h" && cp "$include"/*.h "$work/h/"
    [ -n "$2" ] && sed -e "$3" "$include/$2" >"$work/h/$2"
    if [ -n "$2" ] && cmp -s "$include/$2" "$work/h/$2"; then
        echo "FAIL: $1: the probe changed nothing (has the header changed?)"; fails=$((fails + 1))
    elif sh "$check" "$doxygen" "$work/Doxyfile" "$work/h" "$version" >"$work/out" 2>&1; then
        if [ -z "$4" ]; then passes=$((passes + 1)); else
            echo "FAIL: $1: the check passed"; fails=$((fails + 1)); fi
    elif [ -z "$4" ]; then
        echo "FAIL: $1: the check failed on the unbroken headers:"; cat "$work/out"
        fails=$((fails + 1))
    elif grep -q "$4" "$work/out"; then
        passes=$((passes + 1))
    else
        echo "FAIL: $1: the check failed without naming $4:"; cat "$work/out"; fails=$((fails + 1))
    fi
}
probe "the unbroken headers" "" "" ""
probe "functions outside every group" fricreg_structure_gsl.h \
    '/\\addtogroup structure/,/\\{ \*\//d; /^\/\*\* \\} \*\/$/d' \
    "FAIL: fricreg_structure_set_mass_sparse is in no group"
probe "a broken reference" fricreg.h \
    's/Set every counter to zero\./Set every counter to zero (\\ref no_such_label)./' \
    "fricreg.h:[0-9]*: .*no_such_label"
probe "an undocumented function" fricreg.h '/^\/\*\* Number of contacts m of the context/d' \
    "fricreg.h:[0-9]*: .*fricreg_ctx_size"
echo "$passes passed, $fails failed"
[ $fails -eq 0 ]
