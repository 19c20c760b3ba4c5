#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The core alone builds and passes its tests with every optional part switched off: the GSL
# drivers and CLI, the Fortran interface, the examples (and the benchmarks, off by default).
# The checks of the source tree (label docs) and the sanitizer and valgrind runs (labels
# sanitize, valgrind) run once, in the build that runs this.
# Usage: options_off.sh SOURCE_DIR C_COMPILER
src=$1 cc=$2
work=$(mktemp -d "${TMPDIR:-/tmp}/fricreg-core.XXXXXX")
trap 'rm -rf "$work"' EXIT
cmake -S "$src" -B "$work" -DCMAKE_C_COMPILER="$cc" -DFRICREG_DRIVERS=OFF \
      -DFRICREG_FORTRAN=OFF -DFRICREG_EXAMPLES=OFF -DFRICREG_BENCH=OFF -DFRICREG_PETSC=OFF \
      -DFRICREG_PYTHON=OFF -DFRICREG_OCTAVE=OFF -DFRICREG_MATLAB=OFF >"$work/log" 2>&1 &&
    cmake --build "$work" -j2 >>"$work/log" 2>&1 &&
    (cd "$work" && ctest --output-on-failure -LE "docs|sanitize|valgrind") >>"$work/log" 2>&1
status=$?
grep -E "tests passed|Failed|Error" "$work/log" | tail -n 5
[ $status -eq 0 ] || tail -n 30 "$work/log"
[ $status -eq 0 ] && echo "1 passed, 0 failed" || echo "0 passed, 1 failed"
exit $status
