#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# study.sh — the measurements of docs/structural.md on the building (about 15 s of CPU):
# convergence in dt, accuracy against eps (also on the forced oscillator), Newton iterations,
# central difference's bound and GSL's adaptive steppers against atol (also on the chain).
# Prints plain tables.
#   usage: study.sh PATH/TO/fricreg-sim PATH/TO/make_building DIR
sim=$1; make_building=$2; dir=$3
run() { sh "$(dirname "$0")/run.sh" "$sim" "$make_building" "$dir" "$@" | tail -n 1; }
# roof, dampers, Newton mean/max, failures, residual/input, cpu of a result line
fields() { echo "$1" | awk '{ print $2, $5, $8, $10, $12, $14 }' | tr -d ,; }
rel() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%+.4f %%", 100 * (a / b - 1) }'; }

echo "== reference: Newmark, dt = 1e-4 s, eps = 0.01 m/s"
ref=$(fields "$(run --dt 1e-4)"); echo "$ref"
set -- $ref; ref_roof=$1; ref_D=$2
echo "== convergence in dt (eps = 0.01 m/s): scheme dt roof err D err Newton failures res/input cpu"
for scheme in newmark hht; do
    for dt in 0.02 0.01 0.005 0.001; do
        alpha=""; [ $scheme = hht ] && alpha="--alpha -0.1"
        set -- $(fields "$(run --integrator $scheme $alpha --dt $dt)")
        echo "$scheme $dt $1 $(rel $1 $ref_roof) $2 $(rel $2 $ref_D) $3 $4 $5 $6"
    done
done

for law in quinn tanh; do
    echo "== accuracy against eps, law $law (Newmark, dt = 1e-3 s; reference eps = 1e-5 m/s)"
    set -- $(fields "$(run --law $law --dt 1e-3 --eps 1e-5)"); e_roof=$1; e_D=$2
    echo "1e-5 $*"
    for eps in 0.1 0.03 0.01 0.003 0.001 0.0003 0.0001; do
        set -- $(fields "$(run --law $law --dt 1e-3 --eps $eps)")
        echo "$eps roof $(rel $1 $e_roof) D $(rel $2 $e_D) Newton $3"
    done
done
# The last cycle's dissipation of a fricreg-sim summary.
last_D() { sed -e 's/.*"dissipation_per_cycle": \[[^]]*, \([^],]*\)\].*/\1/'; }
echo "== the forced oscillator (a = 2, omega = 0.5, x0 = 0): D of cycle 10 against eps, RK4"
forced="--a 2 --omega 0.5 --x0 0 --cycles 10"
exact=$("$sim" exact $forced | last_D)
echo "exact $exact; peak velocity $("$sim" oscillator $forced --eps 1e-3 --dt 2e-4 \
    --output trajectory | awk -F, 'NR > 1 { v = $3 < 0 ? -$3 : $3; if (v > V) V = v }
    END { print V }')"
for law in quinn tanh; do
    for eps in 0.3 0.1 0.03 0.01 0.003; do
        dt=$(awk -v e=$eps 'BEGIN { d = 0.2 * e; if (d > 0.01) d = 0.01; print d }')
        D=$("$sim" oscillator --law $law $forced --eps $eps --dt $dt | last_D)
        echo "$law $eps: $(rel $D $exact)"
    done
done
echo "== velocity scale: peak storey drift velocity (m/s) at eps = 1e-3, dt = 1e-3 s"
"$sim" structure --mass "$dir/M.mtx" --stiffness "$dir/K.mtx" \
    --rayleigh "$(cat "$dir/rayleigh.txt")" --contacts "$dir/J.mtx" --mun "$dir/mun.txt" \
    --ground-accel "$dir/ground.txt" --eps 1e-3 --integrator newmark --dt 1e-3 --t-end 15 \
    --output trajectory | awk -F, 'NR > 1 { p = 0; for (i = 12; i <= 21; i++) {
        d = $i - p; p = $i; if (d < 0) d = -d; if (d > V) V = d } } END { print V }'
echo "== default eps (1 % of the ground's peak velocity)"
"$sim" structure --mass "$dir/M.mtx" --stiffness "$dir/K.mtx" \
    --rayleigh "$(cat "$dir/rayleigh.txt")" --contacts "$dir/J.mtx" --mun "$dir/mun.txt" \
    --ground-accel "$dir/ground.txt" --integrator newmark --dt 0.01 --t-end 15 |
    sed -e 's/.*"eps": \([^,]*\),.*/eps \1/'

echo "== Newton iterations (mean/max, failures) against eps and dt (Newmark)"
for eps in 0.03 0.01 0.003 0.001 0.0003 0.0001; do
    line="$eps:"
    for dt in 0.02 0.01 0.005 0.001; do
        set -- $(fields "$(run --dt $dt --eps $eps)")
        line="$line $3 ($4)"
    done
    echo "$line"
done

echo "== central difference: the bound dt < eps/max(2 W_ii mun_i) = eps/17.66 s"
for case in "0.01 0.0005" "0.01 0.0006" "0.1 0.005" "0.1 0.002"; do
    set -- $case
    line=$(run --integrator central --eps $1 --dt $2 2>&1 | tail -n 1)
    set -- $(fields "$line")
    echo "$case: roof $(rel $1 $ref_roof) D $(rel $2 $ref_D) cpu $6 [$line]"
done

echo "== adaptive GSL steppers (eps = 0.01 m/s, rtol = atol)"
for stepper in rkf45 rk8pd; do
    for tol in 1e-3 1e-4 1e-6 1e-8; do
        set -- $(fields "$(run --integrator $stepper --rtol $tol --atol $tol --dt 0.01)")
        echo "$stepper $tol: roof $(rel $1 $ref_roof) D $(rel $2 $ref_D) cpu $6"
    done
done
echo "== rkf45 at eps = 0.001 m/s against Newmark, dt = 1e-3 s, the same eps"
set -- $(fields "$(run --dt 1e-3 --eps 1e-3)"); e_D=$2
for tol in 1e-4 1e-5 1e-6; do
    set -- $(fields "$(run --integrator rkf45 --rtol $tol --atol $tol --eps 1e-3 --dt 0.01)")
    echo "rkf45 $tol: D $(rel $2 $e_D) residual/input $5"
done
echo "== the chain: rkf45, D of cycle 4 against RK4 at dt = 1e-4"
for eps in 1e-2 1e-3; do
    ref=$("$sim" chain --eps $eps --dt 1e-4 | last_D)
    for tol in 1e-3 1e-4 1e-5 1e-6 1e-7; do
        D=$("$sim" chain --eps $eps --dt 1e-3 --integrator rkf45 --rtol $tol --atol $tol | last_D)
        echo "eps $eps tol $tol: $(rel $D $ref)"
    done
done
