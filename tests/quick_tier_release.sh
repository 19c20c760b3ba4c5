#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The quick tier passes in a Release build too (-O3, no debug information): the default build
# type is RelWithDebInfo, and a check that needs debug information (the ABI gate) or a result
# that moves with optimisation must not pass there only. With the long cases the plain quick
# tier leaves to the release tier (FRICREG_QUICK_LONG_CASES): every case in both builds.
# Usage: quick_tier_release.sh SOURCE_DIR C_COMPILER
src=$1 cc=$2
work=$(mktemp -d "${TMPDIR:-/tmp}/fricreg-release.XXXXXX")
trap 'rm -rf "$work"' EXIT
cmake -S "$src" -B "$work" -DCMAKE_C_COMPILER="$cc" -DCMAKE_BUILD_TYPE=Release \
      -DFRICREG_RELEASE_TESTS=OFF -DFRICREG_PETSC=OFF -DFRICREG_QUICK_LONG_CASES=ON >"$work/log" 2>&1 &&
    cmake --build "$work" -j2 >>"$work/log" 2>&1 &&
    ctest --test-dir "$work" -j2 --output-on-failure >>"$work/log" 2>&1
status=$?
grep -E "tests passed|Failed|Error" "$work/log" | tail -n 5
[ $status -eq 0 ] || tail -n 40 "$work/log"
[ $status -eq 0 ] && echo "1 passed, 0 failed" || echo "0 passed, 1 failed"
exit $status
