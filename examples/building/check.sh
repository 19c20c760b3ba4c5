#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# check.sh — the building's acceptance test, from the command line (run.sh): Newmark and
# HHT-alpha (alpha = -0.1) at dt = 0.01 s and 0.005 s with no Newton failure, at most 5
# iterations per step on average, peak roof displacement and damper energy within 0.5 % of a
# fine reference computed here (Newmark, dt = 1e-4 s, itself within 2e-5 of dt = 2e-4 s), and
# Newmark's energy balance closed to 1e-6 of the input work.
#   usage: check.sh PATH/TO/fricreg-sim PATH/TO/make_building DIR
sim=$1; make_building=$2; dir=$3
passed=0; failed=0
result() { sh "$(dirname "$0")/run.sh" "$sim" "$make_building" "$dir" "$@" | tail -n 1; }
# check NAME AWK-CONDITION LINE [REFERENCE-LINE]
check() {
    if echo "$3 ${4:-}" | awk "{ exit !($2) }"; then passed=$((passed + 1))
    else failed=$((failed + 1)); echo "FAIL: $1: $3 (reference: ${4:-none})"; fi
}
# Fields of a result line: $2 roof (m), $5 dampers (J), $8 Newton mean/max, $10 failures,
# $12 residual/input; the reference line's follow from $17 (roof) and $20 (dampers).
ref=$(result --dt 1e-4)
ref2=$(result --dt 2e-4)
echo "reference (dt = 1e-4 s): $ref"
check "reference converged" 'sqrt(($2 / $17 - 1)^2) < 2e-5 && sqrt(($5 / $20 - 1)^2) < 2e-5' "$ref2" "$ref"
for run in "newmark 0.01" "newmark 0.005" "hht 0.01" "hht 0.005"; do
    set -- $run
    alpha=""; [ "$1" = hht ] && alpha="--alpha -0.1"
    line=$(result --integrator "$1" $alpha --dt "$2")
    echo "$1 dt = $2 s: $line"
    check "$1 $2 s: within 0.5 % of the reference" \
        'sqrt(($2 / $17 - 1)^2) <= 5e-3 && sqrt(($5 / $20 - 1)^2) <= 5e-3' "$line" "$ref"
    check "$1 $2 s: Newton" 'split($8, n, "/") == 2 && n[1] + 0 <= 5 && $10 + 0 == 0' "$line"
    [ "$1" = newmark ] && check "$1 $2 s: energy balance" 'sqrt($12^2) <= 1e-6' "$line"
done
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
