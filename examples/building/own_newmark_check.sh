#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# own_newmark_check.sh — the building through the user's own Newmark (own_newmark.f90, with
# fricreg_ctx_solve_step) beside fricreg_structure's run of the same building (the CLI, run.sh)
# at one eps: Newton's mean iterations per step <= 2 and no failed step, and the peak roof
# displacement and the dampers' energy within TOL (relative) of the CLI's.
# Why a tolerance and not bit equality: both solve the same Newmark equations by the same
# Newton (stick guess, stops, line search: its merit sqrt(G^T W G) is the structure's ||J^T G||
# over sqrt(storey mass) here, M = 1e5 I), but the structure solves with CHOLMOD's sparse factor
# and stops on ||J^T G||_inf, this program with LAPACK's and on max |G_i|: sums in another order,
# iterates that differ in their last bits, a step now and then that stops one iteration apart
# within Newton's tolerance. Measured: 4e-16 (roof) and 2e-15 (dampers) relative at
# eps = 1e-3, 0 and 9e-16 at 1e-4. TOL = 1e-10: ample for rounding, far below any change of
# the solution a different step or law would make (eps 1e-3 -> 1e-4 moves the dampers' energy
# by 1.4e-4).
# Plain Newton (no safeguards) is run too and must fail on some steps: the safeguards'
# reason to exist.
#   usage: own_newmark_check.sh fricreg-sim make_building DIR own_newmark EPS
sim=$1; make_building=$2; dir=$3; program=$4; eps=$5
[ -n "$eps" ] || { echo "usage: own_newmark_check.sh fricreg-sim make_building DIR PROGRAM EPS" >&2; exit 2; }
TOL=1e-10
mkdir -p "$dir" || exit 1
line=$(sh "$(dirname "$0")/run.sh" "$sim" "$make_building" "$dir" --eps "$eps" | tail -1) || exit 1
echo "fricreg_structure: $line"
# The summary's peak roof displacement and dampers' energy at full precision (run.sh's line
# rounds the roof to 1e-7 m).
full=$(sed -e 's/.*"peak_displacement": \[[^]]*, \([^],]*\)\].*"friction": \([^,]*\), "residual".*/\1 \2/' \
    "$dir/summary.json")
"$program" "$dir" "$eps" >"$dir/own.txt" || exit 1
"$program" "$dir" "$eps" plain >"$dir/plain.txt" || exit 1
echo "own Newmark:"; cat "$dir/own.txt"
echo "own Newmark, plain Newton:"; cat "$dir/plain.txt"
echo "$full" | awk -v tol=$TOL -v own="$dir/own.txt" -v plain="$dir/plain.txt" '
    { roof = $1; energy = $2 }
    END {
        while ((getline l < own) > 0) { split(l, w, " "); o[w[1]] = w[2] }
        while ((getline l < plain) > 0) { split(l, w, " "); p[w[1]] = w[2] }
        dr = (o["peak_roof_displacement_m"] - roof) / roof; if (dr < 0) dr = -dr
        de = (o["damper_energy_total_J"] - energy) / energy; if (de < 0) de = -de
        printf "relative differences: roof %.2e, dampers %.2e (tolerance %g)\n", dr, de, tol
        bad = 0
        if (o["newton_iterations_mean"] + 0 > 2) { print "FAIL: mean iterations > 2"; bad = 1 }
        if (o["newton_failures"] + 0 != 0) { print "FAIL: failed steps"; bad = 1 }
        if (!(dr <= tol) || !(de <= tol)) { print "FAIL: differs from fricreg_structure"; bad = 1 }
        if (p["newton_failures"] + 0 == 0) { print "FAIL: plain Newton failed nowhere"; bad = 1 }
        exit bad }'
