#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# bench/stress.sh — the numerical stress suite in full mode, from the top of a clone:
#   builds fricreg-stress in build-stress/ (Release) and runs `fricreg-stress --full` on every
#   group (or the groups named: long, extreme, exact, conditioning), printing one table per
#   group with its worst figures, also written to bench-results/stress.txt. 10^7 RK4 steps per
#   reference system, the chain up to n = 10^6, 2000 random exact-solver cases: a few minutes.
#   Exits non-zero if any check failed. ctest runs the short default (label stress).
#   Extra arguments go to the program: e.g. `bench/stress.sh --seed 7 exact`.
set -eu
cd "$(dirname "$0")/.."
start=$(date +%s)
out=bench-results
mkdir -p build-stress "$out"
log=build-stress/stress-build.log
cmake -S . -B build-stress -DCMAKE_BUILD_TYPE=Release -DFRICREG_EXAMPLES=OFF \
      -DFRICREG_FORTRAN=OFF >"$log" 2>&1 || { cat "$log"; exit 1; }
cmake --build build-stress -j2 --target fricreg-stress >>"$log" 2>&1 || { cat "$log"; exit 1; }
{
    echo "date: $(date -u '+%Y-%m-%d %H:%M UTC'), commit $(git rev-parse --short HEAD 2>/dev/null || echo unknown)"
    echo "machine: $(uname -srm), $(nproc) CPUs, load average $(cut -d' ' -f1-3 /proc/loadavg)"
} | tee "$out/stress.txt"
status=0
./build-stress/tests/stress/fricreg-stress --full "$@" | tee -a "$out/stress.txt" || status=1
# tee hides the program's status: read it back from its last line
tail -n 1 "$out/stress.txt" | grep -q '^passed' || status=1
echo "stress suite wall time $(( $(date +%s) - start )) s; tables in $out/stress.txt"
exit $status
