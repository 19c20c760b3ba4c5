#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The doc-comment check can fail: on copies of the headers with one doc comment removed or
# weakened, it must fail and name the declaration. Usage: doc_check_bites.sh CHECK INCLUDE_DIR
check=$1 include=$2
work=$(mktemp -d "${TMPDIR:-/tmp}/fricreg-doc.XXXXXX")
trap 'rm -rf "$work"' EXIT
fails=0 passes=0
probe() { # NAME SED_SCRIPT EXPECTED: breaks fricreg.h's copy, expects EXPECTED in the failure
    rm -rf "$work/h" && mkdir "$work/h" && cp "$include"/*.h "$work/h/"
    sed -e "$2" "$include/fricreg.h" >"$work/h/fricreg.h"
    if cmp -s "$include/fricreg.h" "$work/h/fricreg.h"; then
        echo "FAIL: $1: the probe changed nothing (has the header changed?)"; fails=$((fails + 1))
    elif sh "$check" "$work/h" >"$work/out" 2>&1; then
        echo "FAIL: $1: the check passed"; fails=$((fails + 1))
    elif grep -q "FAIL: .*$3" "$work/out"; then
        passes=$((passes + 1))
    else
        echo "FAIL: $1: the check failed without naming $3:"; cat "$work/out"; fails=$((fails + 1))
    fi
}
probe "function without its comment" '/^\/\*\* Number of contacts m of the context/d' \
    "function fricreg_ctx_size has no doc"
probe "int function without its return codes" \
    's/Returns FRICREG_OK; FRICREG_ENULL; FRICREG_EINVAL for an unknown law or eps < DBL_MIN;/FRICREG_ENULL;/' \
    "function fricreg_ctx_set_law returns int"
probe "enumerator without its comment" 's|FRICREG_ENULL = 1, *[/][*][*]<.*|FRICREG_ENULL = 1,|' \
    "enumerator FRICREG_ENULL"
probe "typedef without its comment" '/^\/\*\* Opaque context for m contacts/d' "typedef"
echo "$passes passed, $fails failed"
[ $fails -eq 0 ]
