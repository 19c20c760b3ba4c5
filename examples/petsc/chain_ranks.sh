#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The chain of 10^6 blocks (examples/petsc/chain.c) dissipates the same energy on 1 and 2
# ranks, to 1e-12 relative: 120 classical RK4 steps of dt = 1e-6 (a stable step, below
# 2.8/(2n)) with the paper's eps = 10 omega dt, from v_i = 1e-4 sin(pi (i + 1/2)/n), so every
# block, on either side of the ranks' cut, slides and sticks.
# Usage: chain_ranks.sh "MPIEXEC -n" PETSC_CHAIN [N] [STEPS]
mpiexec=$1 chain=$2 n=${3:-1000000} steps=${4:-120}
run() {
    $mpiexec "$1" "$chain" -n "$n" -dt 1e-6 -steps "$steps" -v0 1e-4 | tee /dev/stderr |
        awk '/^D = / { print $3 }'
}
d1=$(run 1) d2=$(run 2)
[ -n "$d1" ] && [ -n "$d2" ] || { echo "FAIL: no D (1 rank: '$d1', 2 ranks: '$d2')"; exit 1; }
awk -v a="$d1" -v b="$d2" 'BEGIN {
    d = (b - a) / a; if (d < 0) d = -d
    printf "D on 1 rank = %s, on 2 ranks = %s, relative difference %.3g (<= 1e-12)\n", a, b, d
    exit !(d <= 1e-12) }'
