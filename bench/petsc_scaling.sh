#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The PETSc grid (examples/petsc/grid.c, TSALPHA2 with fricreg's exact tangent) on 1 and 2
# ranks, in one run so that both see the same machine: the median of REPS runs each of
#  - strong scaling: the NX x NX grid on 1 rank, then on 2 (the speed-up, 1 rank / 2 ranks);
#  - weak scaling: NX x NX/2 on 1 rank against NX x NX on 2 (the same nodes per rank).
# Prints each run's line and a table of medians. A figure, not a test (docs/distributed.md):
# run it on idle cores, since a rank that shares its core with another job makes 2 ranks
# slower than 1.
# Usage: bench/petsc_scaling.sh BUILD_DIR [NX] [REPS] [CYCLES]
build=$1 nx=${2:-1000} reps=${3:-3} cycles=${4:-1}
grid=$build/examples/petsc/petsc_grid
[ -x "$grid" ] || { echo "no $grid: build with PETSc (cmake -DFRICREG_PETSC=ON)"; exit 1; }
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
export OMPI_MCA_mpi_yield_when_idle=1
median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
seconds() { # ranks ny: the median seconds of reps runs
    for r in $(seq "$reps"); do
        mpiexec -n "$1" --bind-to none "$grid" -nx "$nx" -ny "$2" -cycles "$cycles" | tee /dev/stderr |
            sed 's/.*seconds = //'
    done | median
}
s1=$(seconds 1 "$nx") s2=$(seconds 2 "$nx")
w1=$(seconds 1 $((nx / 2)))
printf '\n| grid | ranks | nodes per rank | median seconds |\n|---|---|---|---|\n'
printf '| %s x %s | 1 | %s | %s |\n' "$nx" $((nx / 2)) $((nx * nx / 2)) "$w1"
printf '| %s x %s | 1 | %s | %s |\n' "$nx" "$nx" $((nx * nx)) "$s1"
printf '| %s x %s | 2 | %s | %s |\n' "$nx" "$nx" $((nx * nx / 2)) "$s2"
awk -v a="$s1" -v b="$s2" -v w="$w1" 'BEGIN {
    printf "\nspeed-up on 2 ranks (same grid): %.2f; weak-scaling efficiency (same nodes per rank): %.2f\n", a / b, w / b }'
