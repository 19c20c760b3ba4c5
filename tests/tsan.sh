#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# ThreadSanitizer: a third tree with the library and test_threads only, built with
# -fsanitize=thread (which cannot be combined with ASan, so not in sanitize.sh's tree), and
# test_threads run in it: 8 threads with their own objects of every kind (1-D and 2-D contexts,
# Stribeck friction, structures, simulations, exact solutions, harmonic-balance drivers, Iwan
# elements, AFT objects) beside a thread using GSL with
# its own error handler. Any ThreadSanitizer report fails the
# test: reports go to files, which must stay absent. Exits 77 (ctest: skipped) when the
# compiler cannot build and run with -fsanitize=thread.
# Usage: tsan.sh SOURCE_DIR WORK_DIR C_COMPILER
src=$1 work=$2 cc=$3
flags="-fsanitize=thread -fno-omit-frame-pointer -g"
mkdir -p "$work" || exit 1
printf 'int main(void) { return 0; }\n' >"$work/probe.c"
if ! $cc $flags "$work/probe.c" -o "$work/probe" >/dev/null 2>&1 || ! "$work/probe"; then
    echo "SKIP: $cc cannot build and run with $flags"
    exit 77
fi
reports=$work/reports
rm -rf "$reports" && mkdir -p "$reports"
log=$work/log
# Without the warning gate, as sanitize.sh's tree (the instrumentation misleads GCC's warnings).
cmake -S "$src" -B "$work/tree" -DCMAKE_C_COMPILER="$cc" -DFRICREG_FORTRAN=OFF -DFRICREG_WERROR=OFF \
      -DFRICREG_SANITIZE_TREE=ON -DFRICREG_PETSC=OFF -DFRICREG_PYTHON=OFF -DCMAKE_C_FLAGS="$flags" \
      -DCMAKE_EXE_LINKER_FLAGS="$flags" \
      -DCMAKE_SHARED_LINKER_FLAGS="$flags" >"$log" 2>&1 &&
    cmake --build "$work/tree" -j2 --target test_threads >>"$log" 2>&1
built=$?
status=$built
if [ $built -eq 0 ]; then
    TSAN_OPTIONS="log_path=$reports/tsan:halt_on_error=0" CK_DEFAULT_TIMEOUT=1200 \
        "$work/tree/tests/test_threads" >>"$log" 2>&1
    status=$?
fi
grep -E "Checks|Failures|tests/reliability/test_threads.c" "$log" | tail -n 10
count=$(ls "$reports" | wc -l)
if [ "$count" -gt 0 ]; then
    echo "FAIL: $count ThreadSanitizer report(s) in $reports; the first:"
    head -n 60 "$reports/$(ls "$reports" | head -n 1)"
    status=1
fi
[ $built -eq 0 ] || tail -n 30 "$log"
[ $status -eq 0 ] && echo "1 passed, 0 failed" || echo "0 passed, 1 failed"
exit $status
