#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# bench/run.sh — the whole benchmark, from the top of a fresh clone:
#   builds with -DFRICREG_BENCH=ON in build-bench/, runs the work-precision, the scaling, the
#   kernel, the dense and sparse W, the solve_step, the structure-scaling and the membrane's
#   coupled-contact benchmarks,
#   writes every CSV, gnuplot script and PNG to bench-results/, prints the tables (the
#   summary ends the work-precision part), and rewrites the dated results page
#   docs/results.md and the README's summary table from them (commit both to publish a
#   run). Not run by ctest: it takes minutes.
# The event-driven baseline is built when SUNDIALS CVODE is installed (Debian:
# libsundials-dev); without it the rest runs and says so.
set -eu
cd "$(dirname "$0")/.."
start=$(date +%s)
out=bench-results

mkdir -p build-bench "$out"
log=build-bench/bench-build.log
cmake -S . -B build-bench -DFRICREG_BENCH=ON -DFRICREG_TESTS=OFF -DFRICREG_EXAMPLES=OFF \
      -DFRICREG_FORTRAN=OFF >"$log" 2>&1 || { cat "$log"; exit 1; }
cmake --build build-bench -j2 >>"$log" 2>&1 || { cat "$log"; exit 1; }
grep 'fricreg bench:' "$log" || true

{
    echo "date: $(date -u '+%Y-%m-%d %H:%M UTC')"
    echo "machine: $(uname -srm), $(nproc) CPUs," \
         "$(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo | head -n 1)," \
         "load average $(cut -d' ' -f1-3 /proc/loadavg)"
    echo "commit: $(git rev-parse --short HEAD 2>/dev/null || echo unknown)"
} | tee "$out/machine.txt"
echo

./build-bench/bench/fricreg-bench-wp "$out" | tee "$out/workprecision.txt"
echo
./build-bench/bench/fricreg-bench-scaling "$out" | tee "$out/scaling.txt"
echo
./build-bench/bench/fricreg-bench-kernels "$out" | tee "$out/kernels.txt"
echo
./build-bench/bench/fricreg-bench-dense "$out" | tee "$out/dense.txt"
echo
./build-bench/bench/fricreg-bench-sparse "$out" | tee "$out/sparse.txt"
echo
# fricreg_ctx_solve_step with its solver kept in the context, against one built per call.
./build-bench/bench/fricreg-bench-solve-step "$out" | tee "$out/solve_step.txt"
# The 2-D context on stuck chains of 10^2 ... 10^5 contacts (10^6 with FRICREG_BENCH_BIG=1),
# beside the 1-D context on the same data.
./build-bench/bench/fricreg-bench-disk-chain "$out" | tee "$out/disk_chain.txt"
echo
# The problems beyond the paper: the hold, the Stribeck belt and the 2-D oscillator (the last
# two need the CVODE references).
./build-bench/bench/fricreg-bench-problems "$out" | tee "$out/problems.txt"
echo
# A structure's Newmark step from 10^2 to 10^6 degrees of freedom (about 3 minutes).
sh bench/structure_scaling.sh ./build-bench/bench/fricreg-bench-structure-scaling "$out" |
    tee "$out/structure_scaling.txt"
echo
# Coupled contacts on a membrane's edge against a frictionless run (about 4 minutes; the
# 10^6-dof membrane with FRICREG_BENCH_BIG=1).
sh bench/membrane_contacts.sh ./build-bench/bench/fricreg-bench-membrane-contacts "$out" |
    tee "$out/membrane_contacts.txt"
echo
# The chain at n = 1000 and 10^4 against CVODE: minutes of CPU, so only when asked.
if [ "${FRICREG_BENCH_BIG:-0}" = 1 ]; then
    ./build-bench/bench/fricreg-bench-bigchain "$out" 1000 10000 | tee "$out/bigchain.txt"
    echo
fi

if command -v gnuplot >/dev/null 2>&1; then
    (cd "$out" && gnuplot workprecision.gp && gnuplot scaling.gp)
    if [ -f "$out/problems_wp.gp" ]; then (cd "$out" && gnuplot problems_wp.gp); fi
    echo "plots: $(cd "$out" && ls ./*.png | sed 's|^\./||' | tr '\n' ' ')"
else
    echo "gnuplot not found: no PNGs (the .gp scripts and the data are in $out/)"
fi
sh bench/results_page.sh "$out" docs/results.md
sh bench/readme_table.sh "$out" README.md
echo "results in $out/; benchmark wall time $(( $(date +%s) - start )) s"
