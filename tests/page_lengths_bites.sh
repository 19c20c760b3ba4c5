#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The page-length check can fail: on a copy of the tree it passes; a header grown past 800
# lines and a docs page past 900 must each fail it, named; CHANGELOG.md past 900 must not.
# Usage: page_lengths_bites.sh CHECK ROOT
check=$1 root=$2
work=$(mktemp -d "${TMPDIR:-/tmp}/fricreg-page-lengths.XXXXXX")
trap 'rm -rf "$work"' EXIT
mkdir "$work/tree"
for p in include docs fortran python matlab README.md CHANGELOG.md; do
    [ -e "$root/$p" ] && cp -R "$root/$p" "$work/tree/"
done
fails=0 passes=0
grow() { # FILE LINES: FILE to LINES lines
    have=$(wc -l <"$work/tree/$1")
    while [ "$have" -lt "$2" ]; do echo "/* */" >>"$work/tree/$1"; have=$((have + 1)); done
}
outcome() { # NAME EXPECT(pass|FILE)
    if sh "$check" "$work/tree" >"$work/out" 2>&1; then
        [ "$2" = pass ] && passes=$((passes + 1)) && return
        echo "FAIL: $1: the check passed"; fails=$((fails + 1))
    elif [ "$2" != pass ] && grep -q "FAIL: $2 has" "$work/out"; then
        passes=$((passes + 1))
    else
        echo "FAIL: $1:"; cat "$work/out"; fails=$((fails + 1))
    fi
}
outcome "a copy of the tree" pass
cp "$work/tree/include/fricreg.h" "$work/header"
grow include/fricreg.h 801
outcome "a header of 801 lines" include/fricreg.h
cp "$work/header" "$work/tree/include/fricreg.h"
grow include/fricreg.h 800
outcome "a header of 800 lines" pass
cp "$work/header" "$work/tree/include/fricreg.h"
grow docs/python.md 901
outcome "a docs page of 901 lines" docs/python.md
cp "$root/docs/python.md" "$work/tree/docs/python.md"
grow CHANGELOG.md 2000
outcome "the changelog past 900 lines" pass
echo "$passes passed, $fails failed"
[ $fails -eq 0 ]
