#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# ABI check: compares a built libfricreg.so with the committed baseline (abi/fricreg.abi,
# written by abidw) using libabigail's abidiff. Added functions pass (a compatible release
# adds functions in a new version node); any other difference fails: a removed or renamed
# symbol, a changed signature, a changed public type.
# Usage: abi_check.sh BASELINE.abi LIBRARY.so PUBLIC_HEADER_DIR...
# Exit 0: compatible. Exit 1: incompatible or abidiff failed (its report is printed).
baseline=$1 library=$2
shift 2
headers=""
for dir in "$@"; do headers="$headers --hd2 $dir"; done
# --no-added-syms: additions are not reported, so any remaining report is a break.
# shellcheck disable=SC2086
abidiff --no-added-syms $headers "$baseline" "$library"
status=$?
if [ $status -eq 0 ]; then
    echo "abi_check: $library is ABI compatible with $baseline"
    exit 0
fi
echo "abi_check: $library breaks the ABI of $baseline (abidiff status $status)"
exit 1
