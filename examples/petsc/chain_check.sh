#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The chain of 32 blocks through PETSc's TSRK4 (examples/petsc/chain.c) gives the D on cycle 4
# of `fricreg-sim chain` (the library's own RK4 on the same steps, the paper's eps = 10 omega
# dt) to 1e-12 relative. Usage: chain_check.sh FRICREG_SIM "MPIEXEC -n RANKS" PETSC_CHAIN
sim=$1 mpiexec=$2 chain=$3
ref=$("$sim" chain --n 32 --dt 0.01 --cycles 4 | sed 's/.*"dissipation_per_cycle": \[//; s/\].*//' |
    awk -F', ' '{ print $4 }')
out=$($mpiexec "$chain" -n 32 -dt 0.01 -cycles 4) || { echo "FAIL: $chain exited with $?"; exit 1; }
echo "$out"
got=$(echo "$out" | awk '/^D\[4\] = / { print $3 }')
[ -n "$ref" ] && [ -n "$got" ] || { echo "FAIL: no D on cycle 4 (fricreg-sim: '$ref', PETSc: '$got')"; exit 1; }
awk -v r="$ref" -v g="$got" 'BEGIN {
    d = (g - r) / r; if (d < 0) d = -d
    printf "fricreg-sim chain D[4] = %s, PETSc TSRK4 D[4] = %s, relative difference %.3g (<= 1e-12)\n", r, g, d
    exit !(d <= 1e-12) }'
