#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The format check can fail: on a git tree of its own with the project's .clang-format, it
# passes the formatted files and fails each unformatted one, naming it with its count of
# places. Exits 77 (skipped) without clang-format.
# Usage: format_check_bites.sh CHECK ROOT CLANG_FORMAT|-
check=$1 root=$2 clang_format=$3
if [ "$clang_format" = "-" ] || ! command -v "$clang_format" >/dev/null 2>&1; then
    echo "clang-format not found: the format check's probes are skipped"
    exit 77
fi
command -v git >/dev/null 2>&1 || { echo "git not found: the format check's probes are skipped"; exit 77; }
work=$(mktemp -d "${TMPDIR:-/tmp}/fricreg-format-bites.XXXXXX")
trap 'rm -rf "$work"' EXIT
fails=0 passes=0
t=$work/tree
mkdir -p "$t/src"
cp "$root/.clang-format" "$t/"
cp "$root/src/base/error.c" "$t/src/good.c" # formatted, as the format test checks
printf 'int  a ;\nint b;\nint   c;\n' >"$t/src/bad.c"
printf 'int f( void ) ;\n' >"$t/src/bad.h"
(cd "$t" && git init -q && git add -A) || { echo "FAIL: git init"; exit 1; }
if sh "$check" "$t" "$clang_format" >"$work/out" 2>&1; then
    echo "FAIL: the check passed unformatted files"; fails=$((fails + 1))
else
    for expected in "src/bad.c: 3 places" "src/bad.h: 3 places"; do
        if grep -q "^FAIL: $expected not formatted" "$work/out"; then passes=$((passes + 1)); else
            echo "FAIL: the check did not name $expected:"; cat "$work/out"; fails=$((fails + 1)); fi
    done
    if grep -q "good" "$work/out"; then
        echo "FAIL: the check named the formatted file:"; cat "$work/out"; fails=$((fails + 1))
    else
        passes=$((passes + 1))
    fi
fi
rm "$t/src/bad.c" "$t/src/bad.h" && (cd "$t" && git add -A)
if sh "$check" "$t" "$clang_format" >"$work/out" 2>&1; then passes=$((passes + 1)); else
    echo "FAIL: the check failed on formatted files:"; cat "$work/out"; fails=$((fails + 1)); fi
echo "$passes passed, $fails failed"
[ $fails -eq 0 ]
