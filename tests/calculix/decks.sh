#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The tier runs every deck of Debian's calculix-ccx-test that contains *FRICTION: the decks
# of TEST_DIR that do are exactly DECK... (cmake/calculix.cmake's list), so a new version of
# the package with another friction deck is not left out unnoticed.
# Usage: decks.sh TEST_DIR DECK...
dir=$1
shift
expected=$(printf '%s\n' "$@" | sort)
found=$(for f in "$dir"/*.inp "$dir"/*.inp.gz; do
    [ -f "$f" ] && zcat -f "$f" | grep -qi '^\*friction' && basename "${f%.gz}" .inp
done | sort)
if [ "$found" = "$expected" ]; then
    echo "$(echo "$found" | wc -l) decks with *FRICTION in $dir, as listed"
    echo "1 passed, 0 failed"
else
    echo "FAIL: the decks with *FRICTION in $dir and the tier's list differ"
    printf '%s\n' "$found" | grep -vxF -e "$expected" | sed 's/^/  not listed: /'
    printf '%s\n' "$expected" | grep -vxF -e "$found" | sed 's/^/  listed, not found: /'
    echo "0 passed, 1 failed"
    exit 1
fi
