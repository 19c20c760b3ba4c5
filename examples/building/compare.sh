#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# compare.sh — the building example programs (building.c, building.f90) against the CLI's
# summary (run.sh: Newmark, dt = 0.01 s, eps = 0.01 m/s, 15 s): the peak roof displacement,
# each damper's energy and the total, Newton's mean and max iterations and failures, the input
# work and the energy residual must be the same doubles, bit for bit (awk reads both 17-digit
# texts back into doubles and compares them with ==).
# The program's own arguments follow (building_fortran's first is DIR, where run.sh has
# written the building's files).
#   usage: compare.sh PATH/TO/fricreg-sim PATH/TO/make_building DIR PATH/TO/PROGRAM [ARGS...]
sim=$1; make_building=$2; dir=$3; program=$4
shift 4 || { echo "usage: compare.sh fricreg-sim make_building DIR PROGRAM [ARGS]" >&2; exit 2; }
mkdir -p "$dir" || exit 1
sh "$(dirname "$0")/run.sh" "$sim" "$make_building" "$dir" >/dev/null || exit 1
"$program" "$@" >"$dir/program.txt" || exit 1
cat "$dir/program.txt"
# The CLI's numbers as "name value" lines, in the program's names.
sed -e 's/.*"peak_displacement": \[[^]]*, \([^],]*\)\].*"dissipation_per_contact": \[\([^]]*\)\].*"input": \([^,]*\),.*"friction": \([^,]*\), "residual": \([^}]*\)}, "newton_iterations": {"mean": \([^,]*\), "max": \([^}]*\)}, "newton_failures": \([0-9]*\),.*/\1 \2 \3 \4 \5 \6 \7 \8/' \
    "$dir/summary.json" | tr -d , | awk '{
    print "peak_roof_displacement_m", $1
    for (i = 1; i <= 10; i++) print "damper_energy_J", i, $(i + 1)
    print "energy_input_J", $12; print "damper_energy_total_J", $13; print "energy_residual_J", $14
    print "newton_iterations_mean", $15; print "newton_iterations_max", $16
    print "newton_failures", $17 }' >"$dir/cli.txt"
# Every CLI line must be in the program's output with the same value (the per-damper lines are
# keyed by their number too).
awk 'FNR == NR { key = $1 ($1 == "damper_energy_J" ? " " $2 : ""); cli[key] = $NF; n++; next }
     { key = $1 ($1 == "damper_energy_J" ? " " $2 : "")
       if (key in cli) { seen++; if ($NF + 0 != cli[key] + 0) {
           bad++; print "DIFFERS: " key ": program " $NF ", CLI " cli[key] } } }
     END { printf "%d of %d numbers equal to the CLI'"'"'s bit for bit\n", seen - bad, n
           exit !(seen == n && bad == 0) }' "$dir/cli.txt" "$dir/program.txt"
