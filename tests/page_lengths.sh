#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# A reader finds things by object, so no page grows past what one reads at a sitting: no public
# header in include/ over 800 lines (a header per object: fricreg_hb.h and fricreg_structure.h
# include theirs), no guide over 900 (README.md and the Markdown pages of docs/, fortran/,
# python/ and matlab/; CHANGELOG.md, which only grows, excepted).
# Usage: page_lengths.sh ROOT. Names every file over its bound, and fails if there is one.
root=$1
cd "$root" || exit 1
[ -d include ] || { echo "FAIL: no include/ under $root"; exit 1; }
report() { # BOUND WHAT FILE...: a FAIL line for each file over BOUND lines
    bound=$1 what=$2
    shift 2
    for f in "$@"; do
        [ -f "$f" ] || continue
        checked=$((checked + 1))
        lines=$(wc -l <"$f")
        if [ "$lines" -gt "$bound" ]; then
            echo "FAIL: $f has $lines lines, over $bound: split the $what by object"
            fails=$((fails + 1))
        fi
    done
}
checked=0 fails=0
report 800 header include/*.h
report 900 page README.md docs/*.md fortran/*.md python/*.md matlab/*.md
echo "$((checked - fails)) passed, $fails failed"
[ "$fails" -eq 0 ]
