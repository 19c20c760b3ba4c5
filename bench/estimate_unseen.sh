#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# bench/estimate_unseen.sh — the error estimate (1.7's default, two companions) on problems
# its constants were not tuned on, each against a reference that does not share its
# discretization: the belt with Stribeck friction (delta 0.3 … 2, the event-driven reference
# `fricreg-sim belt` prints: stick exact, slip by RK4 at 1e-5 with located ends), its period
# and amplitude; the disk (the reference `fricreg-sim disk` prints, eps 100 times finer); the
# chain of 1000 under central-imex at eps = 2.5 dt (D on cycle 1 against 0.00862894623, RK4
# under the paper's rule extrapolated over 5 levels and rk8pd at rtol 1e-10 over 4, agreeing
# to 3.5e-11). One CSV row per quantity, then the counts: bounded (estimate >= error), within
# 10x, and misses without a warning; per run, the warnings and how many of them are right (the
# error above the answer tolerance, 1e-2), and the runs off by more without one. The frame is
# bench/frame_estimate.c's. About 30 s.
#   usage: bench/estimate_unseen.sh [FRICREG_SIM]
set -eu
sim=${1:-fricreg-sim}
out=$(mktemp)
trap 'rm -f "$out"' EXIT
# The number after "KEY": on stdin (one occurrence: the summary without its reference object,
# or that object alone).
num() { sed -n "s/.*\"$1\": \([-+0-9.eE]*\).*/\1/p"; }
# The summary in $out without its "reference": {...} object, and that object alone.
top() { sed 's/"reference": {[^}]*}//' "$out"; }
ref() { sed -n 's/.*"reference": {\([^}]*\)}.*/\1/p' "$out"; }
rows=$(mktemp)
trap 'rm -f "$out" "$rows"' EXIT
# row PROBLEM SETTING QUANTITY VALUE REFERENCE ESTIMATE
row() {
    warned=$(grep -c '"code": "error_estimate"' "$out" || true)
    echo "$1,$2,$3,$4,$5,$6,$warned" >>"$rows"
}
echo "problem,setting,quantity,value,reference,error,estimate,ratio,warned"
for delta in 0.3 0.5 0.75 1 2; do
    for dt in 0.02 0.01 0.005; do
        "$sim" belt --delta "$delta" --dt "$dt" >"$out" 2>/dev/null
        for q in period amplitude; do
            row belt "delta $delta dt $dt" "$q" "$(top | num "$q")" "$(ref | num "$q")" \
                "$(top | num "${q}_error_estimate")"
        done
    done
done
for a in 1.5 2 3; do
    for dt in 0.02 0.01; do
        "$sim" disk --a "$a" --dt "$dt" >"$out" 2>/dev/null
        row disk "a $a dt $dt" D "$(top | num dissipation_per_cycle)" \
            "$(ref | num dissipation_per_cycle)" "$(top | num dissipation_per_cycle_error_estimate)"
    done
done
for dt in 9e-4 5e-4 2.5e-4 1.25e-4 6.25e-5; do
    eps=$(awk "BEGIN { print 2.5 * $dt }")
    "$sim" chain --n 1000 --integrator central-imex --dt "$dt" --eps "$eps" --cycles 1 \
        >"$out" 2>/dev/null
    row chain1000 "central-imex dt $dt" D \
        "$(sed -n 's/.*"dissipation_per_cycle": \[\([-+0-9.eE]*\)\].*/\1/p' "$out")" \
        0.00862894623 \
        "$(sed -n 's/.*"dissipation_error_estimate": \[\([-+0-9.eE]*\)\].*/\1/p' "$out")"
done
awk -F, '{
    err = $4 - $5; if (err < 0) err = -err
    ratio = err > 0 ? $6 / err : "inf"
    printf "%s,%s,%s,%.12g,%.12g,%.3g,%.3g,%s,%d\n", $1, $2, $3, $4, $5, err, $6, \
           (err > 0 ? sprintf("%.3g", ratio) : "inf"), $7
    n++; b += ($6 >= err); w += ($6 >= err && $6 <= 10 * err); warned += ($7 > 0)
    if ($6 < err && $7 == 0) silent++
    # per run (problem and setting): warned, and its error above the answer tolerance (1e-2)
    run = $1 "," $2; ref = $5 < 0 ? -$5 : $5
    if (!(run in seen)) { seen[run] = 1; runs++ }
    if ($7 > 0) run_warned[run] = 1
    if (err > 1e-2 * ref) off[run] = 1
    if (err > 3e-2 * ref) far[run] = 1
} END {
    printf "# %d quantities: %d bounded (%.1f%%), %d within 10x (%.1f%%), %d warned, " \
           "%d missed without a warning\n", n, b, 100 * b / n, w, 100 * w / n, warned, silent
    for (r in seen) {
        rw += (r in run_warned); right += (r in run_warned) && (r in off)
        unwarned += !(r in run_warned) && (r in off); unwarned3 += !(r in run_warned) && (r in far)
    }
    printf "# %d runs: %d warned, %d of them off by more than the answer tolerance (1e-2); " \
           "%d off by more without a warning (%d by more than 3x)\n", runs, rw, right, \
           unwarned, unwarned3
}' "$rows"
