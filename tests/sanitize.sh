#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# ASan + UBSan: a second tree of the library, its C tests and the Fortran interface, built with
# -fsanitize=address,undefined -fno-sanitize-recover=all and without the AVX2 kernels
# (FRICREG_AVX2=OFF: on an AVX2 machine the main tree never runs the portable loops, and their
# results must be the same bits), and its ctest run (the packaging, ABI
# and source-tree (docs) labels left out: they test files, not memory), its entries with the long
# cases the plain quick tier leaves to the release tier (FRICREG_QUICK_LONG_CASES; not the
# guard's long sweep, guard_long, which runs natively only). Any sanitizer report fails the
# test, also one from a program whose non-zero exit a test expects: reports go to files, which
# must stay absent. Exits 77 (ctest: skipped) when the compiler cannot build and run with the sanitizers.
# Usage: sanitize.sh SOURCE_DIR WORK_DIR C_COMPILER FORTRAN_COMPILER|-
src=$1 work=$2 cc=$3 fc=$4
flags="-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer"
mkdir -p "$work" || exit 1
printf 'int main(void) { return 0; }\n' >"$work/probe.c"
if ! $cc $flags "$work/probe.c" -o "$work/probe" >/dev/null 2>&1 || ! "$work/probe"; then
    echo "SKIP: $cc cannot build and run with $flags"
    exit 77
fi
fortran=-DFRICREG_FORTRAN=OFF
[ "$fc" != - ] && fortran="-DFRICREG_FORTRAN=ON -DCMAKE_Fortran_COMPILER=$fc"
reports=$work/reports
rm -rf "$reports" && mkdir -p "$reports"
log=$work/log
# Without the warning gate: GCC's flow warnings (-Wmaybe-uninitialized) are unreliable under the
# sanitizers' instrumentation (GCC's manual, -fsanitize=address); the plain builds hold the gate.
# No Python binding nor Octave gateway: an instrumented library cannot be loaded into an
# uninstrumented python3 or octave-cli.
# shellcheck disable=SC2086 # $fortran is two words or one, on purpose
cmake -S "$src" -B "$work/tree" -DCMAKE_C_COMPILER="$cc" $fortran -DFRICREG_SANITIZE_TREE=ON -DFRICREG_PETSC=OFF \
      -DFRICREG_QUICK_LONG_CASES=ON \
      -DFRICREG_PYTHON=OFF -DFRICREG_OCTAVE=OFF -DFRICREG_AVX2=OFF -DFRICREG_WERROR=OFF \
      -DCMAKE_C_FLAGS="$flags" -DCMAKE_Fortran_FLAGS="$flags" \
      -DCMAKE_EXE_LINKER_FLAGS="$flags" -DCMAKE_SHARED_LINKER_FLAGS="$flags" >"$log" 2>&1 &&
    cmake --build "$work/tree" -j2 >>"$log" 2>&1
built=$?
status=$built
if [ $built -eq 0 ]; then
    ASAN_OPTIONS="log_path=$reports/asan:detect_leaks=1" \
    UBSAN_OPTIONS="log_path=$reports/ubsan:print_stacktrace=1" \
        ctest --test-dir "$work/tree" -j2 -LE "^(install|abi|docs)$" --output-on-failure >>"$log" 2>&1
    status=$?
fi
grep -E "tests passed|tests failed|Failed|\*\*\*" "$log" | tail -n 20
count=$(ls "$reports" | wc -l)
if [ "$count" -gt 0 ]; then
    echo "FAIL: $count sanitizer report(s) in $reports; the first:"
    cat "$reports/$(ls "$reports" | head -n 1)" | head -n 60
    status=1
fi
[ $built -eq 0 ] || tail -n 30 "$log"
[ $status -eq 0 ] && echo "1 passed, 0 failed" || echo "0 passed, 1 failed"
exit $status
