#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# fricreg-sim's command line: usage errors exit 2 with one line naming the option and write
# nothing to stdout; runs print the paper's numbers. The long runs (hold's 10^7 steps, the belt
# and disk against their references: 9 s of CPU) with FRICREG_CLI_LONG=1 only, the two full
# reproduce runs with FRICREG_CLI_FULL=1 (the release tier's cli_full sets both).
# Usage: cli.sh PATH/TO/fricreg-sim
sim=$1
long=${FRICREG_CLI_LONG:-0}
fails=0
total=0
tmp=${TMPDIR:-/tmp}/fricreg-cli.$$
mkdir -p "$tmp"
trap 'rm -rf "$tmp"' EXIT

# expect_usage_error OPTION-NAMED-IN-MESSAGE ARGS... (an option given twice is refused first:
# the message must say so only where the pattern does, so that no case tests that by mistake)
expect_usage_error() {
    total=$((total + 1))
    named=$1; shift
    "$sim" "$@" >"$tmp/out" 2>"$tmp/err"
    rc=$?
    if [ $rc -ne 2 ] || [ -s "$tmp/out" ] || [ "$(wc -l <"$tmp/err")" -ne 1 ] ||
       ! grep -q -- "$named" "$tmp/err" ||
       { grep -q 'given twice' "$tmp/err" && ! expr "$named" : '.*given twice' >/dev/null; }; then
        echo "FAIL: fricreg-sim $* -> exit $rc, stdout $(wc -c <"$tmp/out") bytes, stderr: $(cat "$tmp/err")"
        fails=$((fails + 1))
    fi
}

# expect_output REGEX ARGS...
expect_output() {
    total=$((total + 1))
    regex=$1; shift
    if ! "$sim" "$@" >"$tmp/out" 2>"$tmp/err" || ! grep -Eq -- "$regex" "$tmp/out"; then
        echo "FAIL: fricreg-sim $* did not print /$regex/: $(head -c 300 "$tmp/out") $(cat "$tmp/err")"
        fails=$((fails + 1))
    fi
}

# expect_in FILE REGEX: what an earlier run wrote into FILE holds the pattern (no rerun).
expect_in() {
    total=$((total + 1))
    if ! grep -Eq -- "$2" "$1"; then
        echo "FAIL: $1 does not hold /$2/: $(head -c 300 "$1")"
        fails=$((fails + 1))
    fi
}

# expect_same TOL ARGS-A -- ARGS-B: two runs print the same JSON summary, every number within
# TOL relative (of 1e-300 at least), all but the CPU seconds (cpu_seconds,
# companion_cpu_seconds), the element kind and sliders, the 2-D elements' forces (which a 1-D
# run does not print) and the contact solver's name.
expect_same() {
    total=$((total + 1))
    tol=$1; shift
    first=""
    while [ "$1" != "--" ]; do first="$first $1"; shift; done
    shift
    for run in a b; do
        if [ $run = a ]; then "$sim" $first >"$tmp/$run" 2>"$tmp/err"; else "$sim" "$@" >"$tmp/$run" 2>"$tmp/err"; fi
        sed -e 's/"cpu_seconds": [0-9.e+-]*//; s/"companion_cpu_seconds": [0-9.e+-]*//; s/"companion_cpu_share": [0-9.e+-]*//; s/, "element_kind": "[^"]*"//; s/, "sliders_per_element": [0-9]*//' \
            -e 's/"contact_solver": "[a-z]*", //' \
            -e 's/, "jenkins_forces": \[[][0-9.e+, -]*\]//' \
            "$tmp/$run" | tr -s ',:[]{} ' '\n' >"$tmp/$run.tokens"
    done
    if [ ! -s "$tmp/a" ] || ! paste "$tmp/a.tokens" "$tmp/b.tokens" | awk -v tol="$tol" -F'\t' '
            $1 == $2 { next }
            $1 + 0 == $1 && $2 + 0 == $2 { d = $1 - $2; s = ($1 < 0 ? -$1 : $1); d = (d < 0 ? -d : d)
                if (d <= tol * (s > 1e-300 ? s : 1e-300)) next }
            { bad++ } END { exit bad > 0 || NR == 0 }'; then
        echo "FAIL: fricreg-sim$first and $* differ: $(head -c 300 "$tmp/a") | $(head -c 300 "$tmp/b") $(cat "$tmp/err")"
        fails=$((fails + 1))
    fi
}

expect_usage_error "unknown command" frobnicate
expect_usage_error "--dt" oscillator --dt -1
expect_usage_error "--dt" oscillator --dt 0
expect_usage_error "--dt" oscillator --dt nan
expect_usage_error "--dt" oscillator --dt inf
expect_usage_error "--dt" oscillator --dt 1e999
# --extrapolate LEVELS (fricreg_sim_run_extrapolated): the sticking oscillator observes
# order 2 (tests/sim/test_extrapolate.c measures it against the exact solution).
expect_usage_error "--extrapolate" oscillator --extrapolate 1
expect_usage_error "--extrapolate" oscillator --extrapolate 9
expect_usage_error "--extrapolate" oscillator --extrapolate 2.5
expect_usage_error "--extrapolate" chain --extrapolate 3 --output trajectory
expect_usage_error "--extrapolate" exact --extrapolate 3
expect_output '"extrapolation": \{"levels": 3, "order": 2, "observed_order": 2\.0[0-4][0-9]*, "flagged_cycles": 0, "eps_finest": 0\.01,' \
    oscillator --a 2 --omega 0.5 --x0 0 --integrator rk8pd --rtol 1e-11 --atol 1e-11 --eps 0.04 --cycles 3 --extrapolate 3
# --extrapolate-order P, --extrapolate-window W (fricreg_sim_run_extrapolated_window): over 12
# cycles with a window of 4, the first 8 cycles and the window's first are not extrapolated
# (estimate +infinity: null in JSON), the last three are (tests/sim/test_extrapolate_window.c).
expect_usage_error "--extrapolate-window" oscillator --extrapolate-window 3
expect_usage_error "--extrapolate-order" oscillator --extrapolate-order 2
expect_usage_error "--extrapolate-order" oscillator --extrapolate 2 --extrapolate-order 5
expect_usage_error "--extrapolate-window" oscillator --extrapolate 2 --extrapolate-window -1
expect_usage_error "--extrapolate-window" oscillator --extrapolate 2 --extrapolate-window 1.5
expect_usage_error "--extrapolate-window" exact --extrapolate-window 3
expect_output '"levels": 2, "order": 2, .*"dissipation_error": null, .*"error_per_cycle": \[null, null, null, null, null, null, null, null, null, [0-9.e-]+, [0-9.e-]+, [0-9.e-]+\]' \
    oscillator --a 2 --omega 0.5 --x0 0 --integrator rk8pd --rtol 1e-10 --atol 1e-10 --eps 0.025 --cycles 12 --extrapolate 2 --extrapolate-order 2 --extrapolate-window 4
expect_usage_error "--dt" oscillator --dt 0.01x
expect_usage_error "--eps" oscillator --eps -0.1
expect_usage_error "--law" oscillator --law sticky
# The valid names come from the library (fricreg_law_name, fricreg_integrator_name).
expect_usage_error "coulomb, force-balance, karnopp, velocity-limited, tanh, quinn" oscillator --law Quinn
expect_usage_error "rk2, rk4, rkf45, rkck, rk8pd, rk1imp, rk2imp, rk4imp, bsimp, msadams, msbdf" chain --integrator rk45
# A command's help lists them too, from the same tables, with the parser's default.
expect_output '^  --law coulomb\|force-balance\|karnopp\|velocity-limited\|tanh\|quinn$' oscillator --help
expect_output '^ +the friction law .*\[quinn\]$' oscillator --help
expect_output '^  --integrator rk2\|rk4\|rkf45\|rkck\|rk8pd\|rk1imp\|rk2imp\|rk4imp\|bsimp\|msadams\|$' chain --help
expect_output '^ +msbdf\|rk4-gsl\|central\|central-imex$' chain --help
expect_output '^ +\(docs/integrators\.md\) \[rk4\]$' chain --help
for law in coulomb force-balance karnopp velocity-limited tanh quinn; do
    expect_output "\"law\": \"$law\"" oscillator --law "$law" --t-end 0.5
done
expect_usage_error "--integrator" chain --integrator euler
expect_usage_error "--omega" chain --omega 0
# A bad parameter value: the option, then the library's message as it is (its range).
expect_usage_error "^fricreg-sim: --omega: .*= 0 must be > 0$" chain --omega 0
expect_usage_error "^fricreg-sim: --n: .*= 2.5 must be an integer from 2 to 10^7$" chain --n 2.5
expect_usage_error "--n" chain --n 1
expect_usage_error "--n" chain --n 2.5
expect_usage_error "--k" oscillator --k 2
expect_usage_error "--mun" oscillator --mun -1
expect_usage_error "--cycles" twoblock --cycles 1.5
expect_usage_error "--t-end" oscillator --t-end 5 --cycles 2
expect_usage_error "--output" oscillator --output xml
expect_usage_error "^fricreg-sim: --a: missing value$" oscillator --a
# An unknown option is unknown also as the last argument (it was a "missing value"), and one
# given twice is refused by name, whichever value was meant, before any file is read.
expect_usage_error "^fricreg-sim: --frobnicate: unknown option for oscillator" oscillator --frobnicate
expect_usage_error "^fricreg-sim: --frobnicate: unknown option for oscillator" oscillator --dt 0.01 --frobnicate
expect_usage_error "^fricreg-sim: --frobnicate: unknown option for structure" structure --mass none.mtx --frobnicate
expect_usage_error "^fricreg-sim: --dt: given twice" oscillator --dt 0.01 --dt 0.02
expect_usage_error "^fricreg-sim: --dt: given twice" oscillator --dt=0.01 --t-end 5 --dt=0.01
expect_usage_error "^fricreg-sim: --cycles: given twice" exact --cycles 2 --cycles 3
expect_usage_error "^fricreg-sim: --mass: given twice" structure --mass none.mtx --mass none2.mtx
expect_usage_error "^fricreg-sim: --omega-start: given twice" hb --omega-start 1 --omega-start 2
expect_usage_error "--rtol" oscillator --rtol -1e-6
# strtod's underflow (ERANGE with a subnormal or zero) is the number written; its overflow
# (ERANGE with HUGE_VAL) is refused. The stuck oscillator keeps a subnormal x0 as it is.
expect_output '"x": \[9\.99999999999996[0-9]*e-311\]' oscillator --x0 1e-310 --t-end 5
expect_output '"x": \[-9\.99999999999996[0-9]*e-311\]' oscillator --x0=-1e-310 --t-end 5
expect_output '"x": \[0\]' oscillator --x0 1e-400 --t-end 5
expect_usage_error "^fricreg-sim: --x0: out of the range of a double$" oscillator --x0 -1e999
expect_usage_error "^fricreg-sim: --dt: must be > 0$" oscillator --dt 1e-400
# A step too large for the stick zone of (4): dt * 2 mun/eps = 5 > 2.78 (RK4).
expect_usage_error "--dt" oscillator --dt 0.05 --eps 0.02
# Under the paper's rule (eps = 2 dt) dt * lambda = 2 mun dt/eps = mun does not depend on dt: mun = 3
# gives 3 > 2.78 at every dt, so the option to change is --eps, and the message says which.
expect_usage_error "^fricreg-sim: --eps: .*at every dt; set eps >= 0.0215827 explicitly$" oscillator --mun 3
expect_usage_error "^fricreg-sim: --dt: .*reduce dt to 0.00926667 or raise eps to 0.0215827$" oscillator --mun 3 --eps 0.02
# Coulomb with rk8pd at dt 3.7 (its imaginary-axis bound) grew the energy 3.78 -> 104: a
# reversal within one step is refused beyond dt * omega = 1/sqrt 2 (src/ode/step_guard.c).
expect_usage_error "^fricreg-sim: --dt: .*> 0.707107 lets a friction reversal" oscillator --law coulomb --integrator rk8pd --dt 3.7
expect_usage_error "--out" reproduce

# Quinn (2004) Sec. 3.1.1: the unforced oscillator sticks at -0.750090.
expect_output '"x": \[-0\.75008[0-9]+' oscillator --t-end 20
# Sec. 3.2, Fig. 9: the chain's D on the 4th cycle is 0.0105 (ours 0.010495).
expect_output '"dissipation_per_cycle": \[[^]]*, 0\.01049[0-9]+\]' chain
expect_output '"stick_fraction": \[0\.[1-9][0-9]*, 0\.[1-9][0-9]*\]' twoblock
# --partition: the two blocks only; the paper's partition gives reproduce's Fig. 11 rows, and
# its coupled stick-zone stiffness 1000 (1 + 1/sqrt 2) refuses dt 0.0025 that the consistent
# law's 1000 accepts (dt * lambda = 4.27 and 2.5 against RK4's 2.785).
expect_usage_error "--partition" twoblock --partition joint
expect_usage_error "--partition" oscillator --partition paper
expect_output '"stick_fraction": \[0\.37878[0-9]*, 0\.44404[0-9]*\]' twoblock --partition paper
expect_output '"stick_fraction": \[0\.37878[0-9]*, 0\.44563[0-9]*\]' twoblock --partition consistent
expect_usage_error "--dt" twoblock --mu1 10 --mu2 5 --eps 0.02 --dt 0.0025 --cycles 2 --partition paper
# ... and under the consistent law that step holds the stick (shared/spec/coupled.md: D of the
# second cycle 6e-9, against 2e-13 at dt 0.0005 and 1.18 where the stick is lost).
expect_output '"dissipation_per_cycle": \[0\.2501[0-9]*, [0-9.]+e-(09|1[0-9])\]' twoblock --mu1 10 --mu2 5 --eps 0.02 --dt 0.0025 --cycles 2 --partition consistent

# Trajectory: header, and one row per GSL step (2 dt for RK4) plus t = 0: 1 + 5/0.02 + header.
"$sim" oscillator --t-end 5 --output trajectory >"$tmp/traj.csv" || fails=$((fails + 1))
[ "$(head -n 1 "$tmp/traj.csv")" = "t,x,v,f,f_eq" ] || { echo "FAIL: trajectory header"; fails=$((fails + 1)); }
rows=$(wc -l <"$tmp/traj.csv")
[ "$rows" -eq 252 ] || { echo "FAIL: trajectory has $rows lines, expected 252"; fails=$((fails + 1)); }

# exact: the closed-form solution of the unforced case sticks at -0.75 exactly (spec); the
# integration options and a trajectory have no meaning for it.
expect_output '"x": \[-0\.75\]' exact --t-end 20
expect_output '"dissipation_per_cycle": \[3\.5, 0, 0\]' exact --t-end 20
# Spec "Forced" (a = 2, omega = 0.5 from rest at the origin): D of cycle 50, 10.4274336336.
expect_output '"dissipation_per_cycle": \[[^]]*, 10\.4274336335[0-9]*\]' exact --a 2 --omega 0.5 --x0 0 --cycles 50
expect_usage_error "--dt" exact --dt 0.01
expect_usage_error "--law" exact --law coulomb
expect_usage_error "--eps" exact --eps 0.02
expect_usage_error "--eps" exact --eps=0.02
expect_usage_error "--output" exact --output trajectory
# A run length the solver refuses (more than 10^6 cycles): the option, then its message.
expect_usage_error "^fricreg-sim: --cycles: .*cycles = 2000000 must be from 1 to 10^6$" exact --cycles 2000000
expect_usage_error "^fricreg-sim: --t-end: .*t_end = 1e+300 .*more than 10^6$" exact --t-end 1e300

# Warnings on a run's settings (fricreg_sim_warning_count): atol = rtol = 1e-6 at eps = 1e-6 holds
# velocities to 2e-6, above 0.01 eps: one line on stderr, one "tol_loose" entry in the JSON, exit 0;
# without --atol (the tolerances from eps) and with fixed steps, none (msbdf's error estimate,
# off here, warns for multistep steppers: below).
total=$((total + 1))
"$sim" twoblock --integrator msbdf --eps 1e-6 --cycles 1 --rtol 1e-6 --atol 1e-6 >"$tmp/out" 2>"$tmp/err"
rc=$?
if [ $rc -ne 0 ] || [ "$(grep -c '^fricreg-sim: warning: .*above 0.01 eps' "$tmp/err")" -ne 1 ] ||
   ! grep -q '"warnings": \[{"code": "tol_loose", "message": "the adaptive steps' "$tmp/out"; then
    echo "FAIL: loose tolerances: exit $rc, stderr $(cat "$tmp/err"), $(tail -c 300 "$tmp/out")"; fails=$((fails + 1))
fi
for args in "twoblock --integrator msbdf --eps 1e-6 --cycles 1 --rtol 1e-6 --error-estimate off" "oscillator"; do
    total=$((total + 1))
    "$sim" $args >"$tmp/out" 2>"$tmp/err"
    if [ -s "$tmp/err" ] || ! grep -q '"warnings": \[\]}$' "$tmp/out"; then
        echo "FAIL: fricreg-sim $args warned: $(cat "$tmp/err") $(tail -c 200 "$tmp/out")"; fails=$((fails + 1))
    fi
done

# The error estimate of D per cycle (fricreg_sim_set_error_estimate): on by default, one number
# per cycle beside dissipation_per_cycle; absent with --error-estimate off.
total=$((total + 1))
"$sim" oscillator --cycles 3 >"$tmp/out" 2>"$tmp/err"
"$sim" oscillator --cycles 3 --error-estimate off >"$tmp/off" 2>>"$tmp/err"
if [ -s "$tmp/err" ] ||
   ! grep -Eq '"dissipation_error_estimate": \[[0-9.e+-]+, [0-9.e+-]+, [0-9.e+-]+\]' "$tmp/out" ||
   grep -q 'error_estimate' "$tmp/off"; then
    echo "FAIL: error estimate: $(cat "$tmp/err") $(cat "$tmp/out") $(cat "$tmp/off")"; fails=$((fails + 1))
fi
# ... each with its kind, and their count; --answer-rtol X warns where the last cycle's estimate
# exceeds X |D| (fricreg_sim_set_answer_rtol), naming it and its kind (cycle 1: 3.6e-5 of D;
# the oscillator sticks after it, D = 0 is exact); X finite and > 0.
expect_output '"dissipation_error_kind": \["(asymptotic|bound)", "(asymptotic|bound)", "(asymptotic|bound)"\], .*"error_estimate_kinds": \{"asymptotic": [0-3], "bound": [0-3], "assumed": 0\}, "cpu_seconds": [0-9.]+, "warnings": \[\]' oscillator --cycles 3
expect_output '"code": "error_estimate", "message": "the error estimate [0-9.e-]+ of cycle 1.s dissipation [0-9.]+ \(asymptotic\) exceeds twice the answer tolerance 1e-05 of it \(the estimate bounds the error at about twice its size\): halve eps and dt, or raise --answer-rtol' oscillator --cycles 1 --answer-rtol 1e-5
expect_usage_error "--answer-rtol" oscillator --answer-rtol 0
# msbdf warns only when its estimate exceeds what the tolerances ask of D (atol + rtol |D|): at
# rtol 1e-6 the estimate 7.1e-5 is above 2.4e-6; at rtol 1e-4, 4.1e-5 is below 2.4e-4.
total=$((total + 1))
"$sim" twoblock --integrator msbdf --eps 1e-4 --cycles 1 --rtol 1e-6 >"$tmp/out" 2>"$tmp/err"
if ! grep -q '"code": "error_estimate", "message": "the error of msadams and msbdf does not follow their tolerances (.*): the error estimate of D, 7.06e-05, is above the 2.36e-06' "$tmp/out"; then
    echo "FAIL: msbdf's estimate did not warn: $(tail -c 400 "$tmp/out")"; fails=$((fails + 1))
fi
total=$((total + 1))
"$sim" twoblock --integrator msbdf --eps 1e-4 --cycles 1 --rtol 1e-4 >"$tmp/out" 2>"$tmp/err"
if [ -s "$tmp/err" ] || ! grep -q '"warnings": \[\]}$' "$tmp/out"; then
    echo "FAIL: msbdf within its tolerances warned: $(cat "$tmp/err") $(tail -c 400 "$tmp/out")"; fails=$((fails + 1))
fi

# ---- structure: a linear structure from Matrix Market files (tests write their own files).
d=$tmp/structure
mkdir -p "$d"
mtx() { # mtx FILE SYMMETRY "rows cols entries" ENTRY-LINES...
    f=$1; sym=$2; size=$3; shift 3
    { echo "%%MatrixMarket matrix coordinate real $sym"; echo "% written by cli.sh"; echo "$size"
      for e in "$@"; do echo "$e"; done; } >"$d/$f"
}
# decoupled PREFIX M1 K1 M2 K2: two uncoupled dofs for element sets on separate blocks, the
# diagonal PREFIXM22.mtx and PREFIXK22.mtx, and each dof's row alone, PREFIXJ1of2.mtx and
# PREFIXJ2of2.mtx (1 x 2).
decoupled() {
    mtx "${1}M22.mtx" symmetric "2 2 2" "1 1 $2" "2 2 $4"
    mtx "${1}K22.mtx" symmetric "2 2 2" "1 1 $3" "2 2 $5"
    mtx "${1}J1of2.mtx" general "1 2 1" "1 1 1"
    mtx "${1}J2of2.mtx" general "1 2 1" "1 2 1"
}
# A rigid block (K = 0: no entries) of m = 3.17 kg on a friction contact of mu N = 4.83 N,
# its ground accelerating at A = 2.41 m/s^2 from t = 0: f_eq = m A = 7.64 N > mu N, so it slides
# from the start at u'' = -(A - mu N/m) = -0.886341 m/s^2 relative to the ground (friction
# opposes the relative velocity, law (4) outside its stick zone): at T = 2.1 s,
# u = -0.886341 T^2/2 = -1.95438123028391 m and the contact dissipated mu N |u| = 9.43966134227
# J. Newmark's average acceleration, RK4 and central difference are all exact for a constant
# acceleration: 12 digits agree (eps = 1e-6 m/s only shifts the first step's force).
mtx M1.mtx symmetric "1 1 1" "1 1 3.17"
mtx K0.mtx symmetric "1 1 0"
mtx J1.mtx general "1 1 1" "1 1 1"
echo 4.83 >"$d/mun1.txt"
printf '# t a_g\n0 2.41\n5 2.41\n' >"$d/ag_const.txt"
block="structure --mass $d/M1.mtx --stiffness $d/K0.mtx --contacts $d/J1.mtx --mun $d/mun1.txt --ground-accel $d/ag_const.txt --eps 1e-6 --t-end 2.1"
expect_output '"x": \[-1\.95438123028[34][0-9]*\]' $block --integrator newmark --dt 0.01
expect_output '"dissipation_per_contact": \[9\.4396613422[67][0-9]*\]' $block --integrator newmark --dt 0.01
# The error estimates of the peak displacement and the dissipation (a companion run at eps/2,
# dt/2): the block's motion is exact in every scheme, so they are at rounding level (a
# companion that moved would show), of kind bound (no order is read from rounding), and the
# summary counts them; none with --error-estimate off.
expect_output '"peak_displacement_error_estimate": \[[0-9.]+e-1[3-9]\], "peak_displacement_error_kind": \["bound"\], "dissipation_per_contact": \[9\.4396613422[67][0-9]*\], "dissipation_per_contact_error_estimate": \[[0-9.]+e-1[2-9]\], "dissipation_per_contact_error_kind": \["bound"\], "error_estimate_kinds": \{"asymptotic": 0, "bound": 2, "assumed": 0\}.*"warnings": \[\]' $block --integrator newmark --dt 0.01
# --answer-rtol (fricreg_structure_set_answer_rtol): an estimate above X times its quantity
# warns error_estimate whatever its kind, here rounding against X = 1e-15; X finite and > 0.
expect_output '"code": "error_estimate", "message": "the error estimate [0-9.e-]+ of the largest peak displacement [0-9.]+ \(kind bound\) exceeds twice the answer tolerance 1e-15 of it \(the estimate bounds the error at about twice its size\): halve eps and dt, or raise --answer-rtol' $block --integrator newmark --dt 0.01 --answer-rtol 1e-15
expect_usage_error "--answer-rtol" $block --integrator newmark --dt 0.01 --answer-rtol 0
expect_usage_error "--answer-rtol" $block --integrator newmark --dt 0.01 --answer-rtol inf
# The companions' CPU seconds (FRICREG_SVALUE_COMPANION_CPU) and where they sit
# (--error-companions, fricreg_structure_set_error_companions), beside cpu_seconds: a share of
# the run's CPU time, so never above it; neither without an estimate. Coarser companions step
# 4 dt per call at least: GSL's fixed steps, called per --dt, are refused. Auto, the default,
# says which gave the estimate: the coarser where quiet (this block at --answer-rtol 1), the
# finer where the screen doubted (at 1e-15), and then what the screen had said.
for companions in finer coarser; do
    expect_output "\"cpu_seconds\": [0-9.]+, \"error_companions\": \"$companions\", \"estimate_companions\": \"$companions\", \"companion_cpu_seconds\": [0-9.]+, \"companion_cpu_share\": [0-9.e-]+, \"warnings\"" $block --integrator newmark --dt 0.01 --error-companions $companions
    total=$((total + 1))
    if ! "$sim" $block --integrator newmark --dt 0.001 --error-companions $companions >"$tmp/out" ||
       ! sed 's/.*"cpu_seconds": \([0-9.]*\).*"companion_cpu_seconds": \([0-9.]*\).*/\1 \2/' "$tmp/out" |
         awk '{ exit !($2 > 0 && $2 <= $1) }'; then
        echo "FAIL: structure --error-companions $companions: companion_cpu_seconds not within cpu_seconds: $(tail -c 160 "$tmp/out")"; fails=$((fails + 1))
    fi
done
total=$((total + 1))
if "$sim" $block --integrator newmark --dt 0.01 --error-estimate off | grep -q companion_cpu_seconds; then
    echo "FAIL: structure --error-estimate off reports companion_cpu_seconds"; fails=$((fails + 1))
fi
expect_usage_error "--error-companions" $block --integrator rk4 --dt 0.01 --error-companions coarser
expect_output '"error_companions": "auto", "estimate_companions": "coarser", "companion_cpu_seconds": [0-9.]+, "companion_cpu_share": [0-9.e-]+, "warnings": \[\]' $block --integrator newmark --dt 0.01 --answer-rtol 1
expect_output '"error_companions": "auto", "estimate_companions": "finer", "companion_cpu_seconds": [0-9.]+, "companion_cpu_share": [0-9.e-]+, "screen": \{"failed": false, "peak_displacement_error": [0-9.e-]+, "dissipation_error": [0-9.e-]+\}, "warnings": \[\{"code": "error_estimate"' $block --integrator newmark --dt 0.01 --answer-rtol 1e-15
expect_output '"error_companions": "auto", "estimate_companions": "finer", .*"screen": \{"failed": true, "peak_displacement_error": null, "dissipation_error": null\}' structure --mass $d/M1.mtx --stiffness $d/K0.mtx --contacts $d/J1.mtx --mun $d/mun1.txt --ground-accel $d/ag_const.txt --eps 1e-2 --t-end 0.1 --integrator rk4 --dt 1e-3
# without an estimate the choice is moot, so not refused: the block's x = -(2.41 - 4.83/3.17)
# t^2 / 2 = -0.0044317 at 0.1 s, no estimate fields
expect_output '"x": \[-0\.0044317[0-9]*\], .*"cpu_seconds": [0-9.]+, "warnings"' structure --mass $d/M1.mtx --stiffness $d/K0.mtx --contacts $d/J1.mtx --mun $d/mun1.txt --ground-accel $d/ag_const.txt --eps 1e-2 --t-end 0.1 --integrator rk4 --dt 1e-3 --error-companions coarser --error-estimate off
expect_usage_error "--error-companions" $block --integrator newmark --dt 0.01 --error-companions coarse
expect_output '"error_companions": "coarser"' $block --integrator rkf45 --dt 0.01 --rtol 1e-6 --error-companions coarser
# --contact-solver (fricreg_structure_set_contact_solver): the summary names the path in force
# (auto: dense for now), and the sparse path's run is the dense one's
expect_output '"integrator": "newmark", "contact_solver": "dense", ' $block --integrator newmark --dt 0.01
expect_output '"integrator": "hht", "alpha": [0-9.e-]+, "contact_solver": "sparse", ' $block --integrator hht --dt 0.01 --contact-solver sparse
expect_same 1e-10 $block --integrator newmark --dt 0.01 --contact-solver dense -- $block --integrator newmark --dt 0.01 --contact-solver sparse
expect_usage_error "--contact-solver" $block --integrator newmark --dt 0.01 --contact-solver cholesky
total=$((total + 1))
if "$sim" $block --integrator newmark --dt 0.01 --error-estimate off 2>&1 | grep -q error_estimate; then
    echo "FAIL: structure --error-estimate off still estimates"; fails=$((fails + 1))
fi
expect_output '"peak_displacement": \[1\.95438123028[34][0-9]*\]' $block --integrator hht --alpha -0.1 --dt 0.01
# GSL's adaptive steppers without --atol take the tolerances from eps
# (FRICREG_ATOL_FROM_EPS): the velocity, which the contact reads, to min(1e-3 eps, rtol) =
# 1e-9 m/s with no relative part, the others (u, W_in, E_visc, D) to rtol; --atol A gives A in
# every component, as before 1.6. The block's motion stays exact under rkf45 either way.
expect_output '"atol": "eps", .*"x": \[-1\.95438123028[34][0-9]*\], .*"atol_used": \[9\.9999999999999995e-07, 1\.0000000000000001e-09, 9\.9999999999999995e-07, 9\.9999999999999995e-07, 9\.9999999999999995e-07\]' $block --integrator rkf45 --dt 0.01 --rtol 1e-6
expect_output '"atol": 9\.9999999999999995e-07, .*"atol_used": \[(9\.9999999999999995e-07(, )?){5}\]' $block --integrator rkf45 --dt 0.01 --rtol 1e-6 --atol 1e-6
# msbdf needs atol > 0: without --atol it was refused, now it takes the rule
expect_output '"atol": "eps"' $block --integrator msbdf --dt 0.01 --rtol 1e-6
# Warnings (fricreg_structure_warning_count, docs/structural.md "Warnings"): the block in SI
# units raises none (record peak 2.41 m/s^2 = 0.246 g inside 0.05 g .. 5 g; eps = 1e-6 m/s
# inside 1e-9 .. 0.1 of the ground's peak velocity 12.05 m/s; mu N/m = 1.52 m/s^2 = 0.155 g
# inside 1e-3 g .. 10 g; the block slides at up to 1.86 m/s > 10 eps; K = 0: no fundamental
# period); the same record typed in g (2.41/9.81 = 0.2457, below 0.05 g = 0.49 m/s^2) raises
# ground_peak, once on stderr and in the JSON, and the exit status stays 0.
total=$((total + 1))
if ! "$sim" $block --integrator newmark --dt 0.01 >"$tmp/out" 2>"$tmp/err" || [ -s "$tmp/err" ] ||
   ! grep -q '"warnings": \[\]}$' "$tmp/out"; then
    echo "FAIL: structure in SI units: warnings: $(cat "$tmp/err") $(tail -c 200 "$tmp/out")"; fails=$((fails + 1))
fi
printf '# t a_g (in g: a unit mistake)\n0 0.2457\n5 0.2457\n' >"$d/ag_g.txt"
total=$((total + 1))
if ! "$sim" structure --mass $d/M1.mtx --stiffness $d/K0.mtx --contacts $d/J1.mtx --mun $d/mun1.txt --ground-accel $d/ag_g.txt --eps 1e-6 --t-end 2.1 --integrator newmark --dt 0.01 >"$tmp/out" 2>"$tmp/err" ||
   [ "$(grep -c '^fricreg-sim: warning: the ground acceleration record peaks at 0.2457 m/s^2' "$tmp/err")" -ne 1 ] ||
   ! grep -q '"warnings": \[{"code": "ground_peak", "message": "the ground acceleration record peaks at 0.2457 m/s^2' "$tmp/out"; then
    echo "FAIL: structure with a record in g: stderr $(cat "$tmp/err"), $(tail -c 300 "$tmp/out")"; fails=$((fails + 1))
fi
expect_output '"x": \[-1\.95438123028[34][0-9]*\]' structure --mass $d/M1.mtx --stiffness $d/K0.mtx --contacts $d/J1.mtx --mun $d/mun1.txt --ground-accel $d/ag_const.txt --eps 0.01 --t-end 2.1 --integrator rk4 --dt 0.005
expect_output '"x": \[-1\.95438123028[34][0-9]*\]' structure --mass $d/M1.mtx --stiffness $d/K0.mtx --contacts $d/J1.mtx --mun $d/mun1.txt --ground-accel $d/ag_const.txt --eps 0.01 --t-end 2.1 --integrator central --dt 0.002
# A record's subnormal sample (a ground acceleration of 1e-310 at t = 5, after the run's end)
# is the number written, as on the command line, not "not finite": the same run.
# A record whose times are subnormal (0, 1e-310, 2e-310 s): the default eps, 1 % of its peak
# ground velocity (2e-310 m/s), is below DBL_MIN; the message names the record, not --eps,
# which was not given.
printf '0 1\n1e-310 1\n2e-310 1\n' >"$d/ag_subnormal_times.txt"
expect_usage_error '^fricreg-sim: --ground-accel: the default eps, 1 % of the record.s peak ground velocity, is 2e-312' structure --mass $d/M1.mtx --stiffness $d/K0.mtx --contacts $d/J1.mtx --mun $d/mun1.txt --ground-accel $d/ag_subnormal_times.txt --t-end 1 --integrator newmark --dt 0.01
printf '# t a_g\n0 2.41\n2.5 2.41\n5 1e-310\n' >"$d/ag_subnormal.txt"
expect_output '"x": \[-1\.95438123028[34][0-9]*\]' structure --mass $d/M1.mtx --stiffness $d/K0.mtx --contacts $d/J1.mtx --mun $d/mun1.txt --ground-accel $d/ag_subnormal.txt --eps 1e-6 --t-end 2.1 --integrator newmark --dt 0.01
# without --integrator: Newmark, the summary naming it, the same numbers bit for bit
expect_output '"integrator": "newmark"' structure --mass $d/M1.mtx --stiffness $d/K0.mtx --contacts $d/J1.mtx --mun $d/mun1.txt --ground-accel $d/ag_g.txt --eps 1e-6 --t-end 2.1 --dt 0.01
expect_same 0 structure --mass $d/M1.mtx --stiffness $d/K0.mtx --contacts $d/J1.mtx --mun $d/mun1.txt --ground-accel $d/ag_g.txt --eps 1e-6 --t-end 2.1 --dt 0.01 -- structure --mass $d/M1.mtx --stiffness $d/K0.mtx --contacts $d/J1.mtx --mun $d/mun1.txt --ground-accel $d/ag_g.txt --eps 1e-6 --t-end 2.1 --dt 0.01 --integrator newmark
# Its energy balance: input m A |u| = 14.9308862850 J, kinetic m (0.886341 T)^2/2 = 5.49122494 J.
# Newton needs no iteration: the step's start forces (sliding, -mu N) are its solution exactly.
expect_output '"input": 14\.930886285[0-9]*, "kinetic": 5\.4912249[0-9]*, "strain": 0, "viscous": 0, "friction": 9\.43966134[0-9]*, "residual": -?[0-9.]+e-1[3-9]\}, "newton_iterations": \{"mean": 0, "max": 0\}, "newton_failures": 0' $block --integrator newmark --dt 0.01
# Comment and blank lines anywhere, CRLF line ends and a trailing blank line (which GSL's own
# reader refuses after the size line) read as the plain file does.
printf '%%%%MatrixMarket matrix coordinate real symmetric\r\n%% mass\r\n\r\n1 1 1\r\n%% kg\r\n\r\n1 1 3.17\r\n\r\n' >"$d/M1crlf.mtx"
expect_output '"x": \[-1\.95438123028[34][0-9]*\]' structure --mass $d/M1crlf.mtx --stiffness $d/K0.mtx --contacts $d/J1.mtx --mun $d/mun1.txt --ground-accel $d/ag_const.txt --eps 1e-6 --t-end 2.1 --integrator newmark --dt 0.01
expect_output '^usage: fricreg-sim structure --mass M\.mtx --stiffness K\.mtx' structure --help
expect_output '^  structure   ' --help
# The default eps is 1 % of the ground's peak velocity, here 2.41 m/s^2 * 5 s = 12.05 m/s (the
# record's length), and 1e-3 without ground motion (docs/structural.md).
expect_output '"eps": 0\.1205(0000+[0-9]*)?,' structure --mass $d/M1.mtx --stiffness $d/K0.mtx --contacts $d/J1.mtx --mun $d/mun1.txt --ground-accel $d/ag_const.txt --t-end 2.1 --integrator newmark --dt 0.01
expect_output '"eps": 0\.001(0000+[0-9]*)?,' structure --mass $d/M1.mtx --stiffness $d/K0.mtx --contacts $d/J1.mtx --mun $d/mun1.txt --t-end 2.1 --integrator newmark --dt 0.01
# Central difference: dt times the stick-zone stiffness 2 mu N/(m eps) = 304.7/s must be < 1.
expect_usage_error "^fricreg-sim: --dt: .*too large for the stick zone" structure --mass $d/M1.mtx --stiffness $d/K0.mtx --contacts $d/J1.mtx --mun $d/mun1.txt --ground-accel $d/ag_const.txt --eps 0.01 --t-end 2.1 --integrator central --dt 0.005

# An undamped oscillator, m = 2.385 kg, k = 417.3 N/m (w = 13.2277/s), no friction (mu N = 0),
# under a constant ground acceleration A = 0.731 m/s^2: average-acceleration Newmark gives
# u_n = -(A/w^2)(1 - cos(W n dt)) exactly, W = (2/dt) atan(w dt/2) = 13.20833/s at dt = 0.01
# s: u(1.37 s) = -0.00113279590437900 m (the continuous solution's w would give -0.0010585).
mtx M2.mtx symmetric "1 1 1" "1 1 2.385"
mtx K2.mtx symmetric "1 1 1" "1 1 417.3"
echo 0 >"$d/mun0.txt"
printf '0 0.731\n10 0.731\n' >"$d/ag_osc.txt"
expect_output '"x": \[-0\.00113279590437[89][0-9]*\]' structure --mass $d/M2.mtx --stiffness $d/K2.mtx --contacts $d/J1.mtx --mun $d/mun0.txt --ground-accel $d/ag_osc.txt --integrator newmark --dt 0.01 --t-end 1.37
# ... its energy balance closes (input = kinetic + strain) to Newton's tolerance.
expect_output '"residual": -?[0-9.]+e-(1[3-9]|[2-9][0-9])' structure --mass $d/M2.mtx --stiffness $d/K2.mtx --contacts $d/J1.mtx --mun $d/mun0.txt --ground-accel $d/ag_osc.txt --integrator newmark --dt 0.01 --t-end 1.37
# The same oscillator without --contacts and --mun: no friction contacts, plain linear
# dynamics. Its trajectory has no force columns, and every row is the discrete closed form
# above to 1e-11 of A/w^2 (rounding over 137 steps), and within (A/w^2) (w - W) t of the
# continuous u(t) = -(A/w^2)(1 - cos(w t)) (the scheme's second-order phase error,
# w - W = w^3 dt^2/12 + O(dt^4) = 1.93e-3/s).
# osc_check FILE P_OVER_K: FILE's rows (t, u1, v1) against u = P_OVER_K (1 - cos(w t)).
osc_check() {
    total=$((total + 1))
    if [ "$(head -n 1 "$1")" != "t,u1,v1" ] || [ "$(wc -l <"$1")" -ne 139 ] ||
       ! awk -F, -v s="$2" 'NR > 1 { w = sqrt(417.3 / 2.385); W = 2 / 0.01 * atan2(w * 0.01 / 2, 1)
            d = $2 - s * (1 - cos(W * $1)); c = $2 - s * (1 - cos(w * $1)); a = s < 0 ? -s : s
            if (d > 1e-11 * a || d < -1e-11 * a || c > a * (w - W) * $1 || c < -a * (w - W) * $1) exit 1 }' "$1"; then
        echo "FAIL: $1 is not the oscillator's closed form (P/k = $2): $(head -n 3 "$1") ... $(wc -l <"$1") lines"; fails=$((fails + 1))
    fi
}
osc="structure --mass $d/M2.mtx --stiffness $d/K2.mtx --integrator newmark --dt 0.01 --t-end 1.37"
expect_output '"ncontacts": 0, "x": \[-0\.00113279590437[89][0-9]*\],.*"dissipation_per_contact": \[\]' $osc --ground-accel $d/ag_osc.txt
"$sim" $osc --ground-accel $d/ag_osc.txt --output trajectory >"$d/osc_free.csv" 2>"$tmp/err"
osc_check "$d/osc_free.csv" "$(awk 'BEGIN { printf "%.17g", -0.731 * 2.385 / 417.3 }')"
# An external load p(t) = P g(t) (--load, --load-history): P = 1.93 N, a step g = 1 from t = 0,
# gives u = (P/k)(1 - cos(w t)) by the same closed forms; without --load-history g = 1 at all
# times, the same rows; and P = m A beside the ground's A cancels it: p - M r a_g = 0, u = 0
# to the rounding of m A (1e-16 of u's scale A/w^2 = 4e-3 m: 4e-19 m).
mtx P2.mtx general "1 1 1" "1 1 1.93"
mtx PmA.mtx general "1 1 1" "1 1 1.743435"
printf '# t g\n0 1\n10 1\n' >"$d/g_step.txt"
"$sim" $osc --load $d/P2.mtx --load-history $d/g_step.txt --output trajectory >"$d/osc_load.csv" 2>"$tmp/err"
osc_check "$d/osc_load.csv" "$(awk 'BEGIN { printf "%.17g", 1.93 / 417.3 }')"
"$sim" $osc --load $d/P2.mtx --output trajectory >"$d/osc_const.csv" 2>"$tmp/err"
total=$((total + 1))
if [ ! -s "$d/osc_const.csv" ] || ! cmp -s "$d/osc_load.csv" "$d/osc_const.csv"; then
    echo "FAIL: a load without --load-history is not g = 1: $(head -n 3 "$d/osc_const.csv")"; fails=$((fails + 1))
fi
expect_output '"x": \[(0|-?[0-9.]+e-(19|[2-9][0-9]))\]' $osc --load $d/PmA.mtx --ground-accel $d/ag_osc.txt --error-estimate off
expect_usage_error "^fricreg-sim: --load-history: .*give both" $osc --load-history $d/g_step.txt
mtx P21.mtx general "2 1 1" "1 1 1.93"
printf '0 1\n' >"$d/g_one.txt"
expect_usage_error "^fricreg-sim: --load $d/P21.mtx: the matrix is 2 x 1, expected 1 x 1" $osc --load $d/P21.mtx
expect_usage_error "^fricreg-sim: --load-history $d/g_one.txt: 1 samples" $osc --load $d/P2.mtx --load-history $d/g_one.txt
expect_usage_error "^fricreg-sim: --mun: missing: --contacts and --mun come together" $osc --contacts $d/J1.mtx
expect_usage_error "^fricreg-sim: --contacts: missing: --contacts and --mun come together" $osc --mun $d/mun0.txt
expect_usage_error "^fricreg-sim: --eps: .*without --contacts there is none" $osc --eps 0.01
# The same with 200.0 of the 417.3 N/m a stuck Jenkins element (--jenkins, mu N = 1e30 N): a
# spring kt, so the same closed form; with mu N = 0.05 N it slips (its dissipation > 0) and the
# balance still closes.
mtx K2a.mtx symmetric "1 1 1" "1 1 217.3"
echo "200.0 1e30" >"$d/P_stuck.txt"
echo "200.0 0.05" >"$d/P_slip.txt"
jk="structure --mass $d/M2.mtx --stiffness $d/K2a.mtx --contacts $d/J1.mtx --mun $d/mun0.txt --ground-accel $d/ag_osc.txt --jenkins $d/J1.mtx --dt 0.01 --t-end 1.37"
expect_output '"x": \[-0\.00113279590437[89][0-9]*\].*"njenkins": 1, "dissipation_per_jenkins": \[0\]' $jk --jenkins-params $d/P_stuck.txt --integrator newmark
expect_output '"jenkins_dissipation": 0\.0[0-9]*[1-9].*"jenkins": 0\.0[0-9]*[1-9][0-9]*, "residual": -?[0-9.]+e-(1[3-9]|[2-9][0-9])' $jk --jenkins-params $d/P_slip.txt --integrator newmark
# Central difference is exact for it too, with W = (2/dt) asin(w dt/2) = 13.23717/s:
# u(1.37 s) = -0.00102196310005633 m.
expect_output '"x": \[-0\.00102196310005[56][0-9]*\]' $jk --jenkins-params $d/P_stuck.txt --integrator central
expect_usage_error "^fricreg-sim: --jenkins-params: missing" structure --mass $d/M2.mtx --stiffness $d/K2a.mtx --contacts $d/J1.mtx --mun $d/mun0.txt --jenkins $d/J1.mtx --integrator newmark --dt 0.01 --t-end 1
expect_usage_error "^fricreg-sim: --jenkins: Jenkins elements are integrated by newmark" $jk --jenkins-params $d/P_stuck.txt --integrator rk4
# Elements beside a contact of bound > 0 step together (docs/joints.md): on the sliding block
# above, an element of bound 0 carries no force (its closed form holds), and one of bound
# 0.05 N slips beside the contact, both dissipating, the balance closing.
echo "200.0 0" >"$d/P_free.txt"
expect_output '"x": \[-1\.95438123028[34][0-9]*\].*"dissipation_per_contact": \[9\.4396613422[67][0-9]*\],.*"njenkins": 1, "dissipation_per_jenkins": \[0\]' $block --jenkins $d/J1.mtx --jenkins-params $d/P_free.txt --integrator newmark --dt 0.01
# the slipping element's dissipation carries its error estimate (the companions at dt/2, dt/4)
expect_output '"dissipation_per_contact": \[9\.[0-9]+\],.*"njenkins": 1, "dissipation_per_jenkins": \[0\.09[0-9]+\], "dissipation_per_jenkins_error_estimate": \[[0-9.]+e-[0-9]+\].*"residual": -?[0-9.]+e-(1[3-9]|[2-9][0-9])' $block --jenkins $d/J1.mtx --jenkins-params $d/P_slip.txt --integrator newmark --dt 0.01
echo "-1 0.05" >"$d/P_bad.txt"
expect_usage_error "^fricreg-sim: --jenkins-params $d/P_bad.txt: .*kt = -1 must be > 0" $jk --jenkins-params $d/P_bad.txt --integrator newmark
# Checkpoints (--checkpoint-out, --checkpoint-in; fricreg_structure_save/_restore): the run to
# 0.5 s saved and continued to 1 s in another process is the run to 1 s, byte for byte: its
# trajectory (the continued run's rows after its first, which repeats the checkpoint's time) and
# its summary with the error estimate's companions (but the CPU time). 0.5 is a step time of
# dt = 0.01 (the rounded 50 dt is 0.5), so the uninterrupted run steps through it. The scene
# slips and sticks: a contact of 0.3 N beside a slipping Jenkins element under the step of
# 0.731 m/s^2 slides back and forth through 0.5 s and sticks from 0.62 s (eps = 1e-3 m/s; the
# explicit schemes need 0.05 for their step guard). The finer companions: the default, auto,
# decides at each call's end, so a run split in two may confirm at 0.5 s where the run in one
# call is quiet at 1 s; auto's own case after the loop keeps its screen quiet (--answer-rtol
# 1), its finer pair parked through the checkpoint.
echo 0.3 >"$d/mun_ck.txt"
ck="structure --mass $d/M2.mtx --stiffness $d/K2a.mtx --contacts $d/J1.mtx --mun $d/mun_ck.txt --ground-accel $d/ag_osc.txt --dt 0.01"
fin="--error-companions finer"
for integ in "newmark --eps 1e-3 --jenkins $d/J1.mtx --jenkins-params $d/P_slip.txt $fin" \
    "hht --eps 1e-3 --jenkins $d/J1.mtx --jenkins-params $d/P_slip.txt $fin" \
    "central --eps 0.05 --jenkins $d/J1.mtx --jenkins-params $d/P_slip.txt $fin" \
    "rk4 --eps 0.05 $fin" "rkf45 --eps 1e-3 --rtol 1e-6 $fin"; do
    for out in trajectory summary; do
        rm -f "$tmp/ck.bin"
        "$sim" $ck --integrator $integ --output $out --t-end 1 >"$tmp/full" 2>/dev/null &&
        "$sim" $ck --integrator $integ --output $out --t-end 0.5 --checkpoint-out "$tmp/ck.bin" >"$tmp/part1" 2>/dev/null &&
        "$sim" $ck --integrator $integ --output $out --t-end 1 --checkpoint-in "$tmp/ck.bin" >"$tmp/part2" 2>"$tmp/err"
        status=$?
        if [ $out = trajectory ]; then
            { cat "$tmp/part1"; tail -n +3 "$tmp/part2"; } >"$tmp/split"
        else
            sed 's/"cpu_seconds": [0-9.]*//; s/"companion_cpu_seconds": [0-9.]*//; s/"companion_cpu_share": [0-9.e+-]*//' "$tmp/part2" >"$tmp/split"
            sed -i 's/"cpu_seconds": [0-9.]*//; s/"companion_cpu_seconds": [0-9.]*//; s/"companion_cpu_share": [0-9.e+-]*//' "$tmp/full"
        fi
        if [ $status -ne 0 ] || [ ! -s "$tmp/full" ] || ! cmp -s "$tmp/full" "$tmp/split"; then
            echo "FAIL: structure --integrator $integ --output $out: split at 0.5 s != the run to 1 s (status $status: $(cat "$tmp/err"))"; fails=$((fails + 1))
        fi
    done
done
# Auto, split: the checkpoint is written before the first half's summary reads (and settles)
# the screen, so the continued run is judged at 1 s as the run in one call: at --answer-rtol
# 0.1 the first half's summary is confirmed by the finer companions at 0.5 s, yet the
# continued run, as the run in one call, keeps the quiet screen at 1 s; at 1e-2 both are
# confirmed. At dt = 0.0125 s, 0.5 s is a step time of the coarsest companion too (4 dt; at
# 0.01 s its grid, and so the coarser estimate, differs in the two halves).
strip_cpu() { sed 's/"cpu_seconds": [0-9.e+-]*//; s/"companion_cpu_seconds": [0-9.e+-]*//; s/"companion_cpu_share": [0-9.e+-]*//' "$1"; }
for rtol in 0.1 1e-2; do
    ck_auto="structure --mass $d/M2.mtx --stiffness $d/K2a.mtx --contacts $d/J1.mtx --mun $d/mun_ck.txt --ground-accel $d/ag_osc.txt --dt 0.0125 --integrator newmark --eps 1e-3 --jenkins $d/J1.mtx --jenkins-params $d/P_slip.txt --answer-rtol $rtol"
    total=$((total + 1))
    [ $rtol = 0.1 ] && by=coarser || by=finer
    if ! "$sim" $ck_auto --t-end 1 >"$tmp/full" || ! grep -q "\"estimate_companions\": \"$by\"" "$tmp/full" ||
       ! "$sim" $ck_auto --t-end 0.5 --checkpoint-out "$tmp/ck.bin" >"$tmp/part1" ||
       ! grep -q '"estimate_companions": "finer"' "$tmp/part1" ||
       ! "$sim" $ck_auto --t-end 1 --checkpoint-in "$tmp/ck.bin" >"$tmp/part2" ||
       [ "$(strip_cpu "$tmp/full")" != "$(strip_cpu "$tmp/part2")" ]; then
        echo "FAIL: structure --error-companions auto --answer-rtol $rtol: split at 0.5 s != the run to 1 s: $(head -c 200 "$tmp/full")"; fails=$((fails + 1))
    fi
done
"$sim" $ck --integrator newmark --t-end 0.5 --checkpoint-out "$tmp/ck.bin" >/dev/null 2>&1
expect_usage_error "^fricreg-sim: --checkpoint-in $d/none.bin: cannot open" $ck --integrator newmark --t-end 1 --checkpoint-in "$d/none.bin"
expect_usage_error "^fricreg-sim: --checkpoint-in $tmp/ck.bin: restore: .*bounds mun .* not the checkpoint's" structure --mass $d/M2.mtx --stiffness $d/K2a.mtx --contacts $d/J1.mtx --mun $d/mun1.txt --ground-accel $d/ag_osc.txt --dt 0.01 --integrator newmark --t-end 1 --checkpoint-in "$tmp/ck.bin"
expect_usage_error "^fricreg-sim: --checkpoint-in $tmp/ck.bin: restore: .*alpha" $ck --integrator hht --t-end 1 --checkpoint-in "$tmp/ck.bin"
expect_usage_error "^fricreg-sim: --t-end: must be after the checkpoint's time 0.5" $ck --integrator newmark --t-end 0.4 --checkpoint-in "$tmp/ck.bin"
head -c 100 "$tmp/ck.bin" >"$tmp/ck_cut.bin"
expect_usage_error "^fricreg-sim: --checkpoint-in $tmp/ck_cut.bin: restore: .*truncated" $ck --integrator newmark --t-end 1 --checkpoint-in "$tmp/ck_cut.bin"
# A --checkpoint-out that cannot be written (a file-size limit of 0, SIGXFSZ ignored so that
# the write fails with EFBIG; stderr through a pipe, which the limit spares) says why, and
# leaves the previous checkpoint as it was and no temporary file; a device is never replaced.
cp "$tmp/ck.bin" "$tmp/ck_before.bin"
total=$((total + 1))
msg=$( (trap '' XFSZ; ulimit -f 0; "$sim" $ck --integrator newmark --t-end 0.7 --checkpoint-out "$tmp/ck.bin" 2>&1 >/dev/null); echo "exit $?")
if ! echo "$msg" | grep -q "^fricreg-sim: --checkpoint-out $tmp/ck.bin: cannot write: File too large$" ||
   [ "$(echo "$msg" | tail -n 1)" != "exit 2" ] ||
   ! cmp -s "$tmp/ck.bin" "$tmp/ck_before.bin" || ls "$tmp"/.ck.bin.* >/dev/null 2>&1; then
    echo "FAIL: a failed --checkpoint-out: $msg; the checkpoint kept: $(cmp "$tmp/ck.bin" "$tmp/ck_before.bin"); left: $(ls -a "$tmp" | grep '^\.ck')"
    fails=$((fails + 1))
fi
total=$((total + 1))
"$sim" $ck --integrator newmark --t-end 0.5 --checkpoint-out /dev/full >"$tmp/out" 2>"$tmp/err"
if [ $? -ne 2 ] || [ -s "$tmp/out" ] ||
   ! grep -q "^fricreg-sim: --checkpoint-out /dev/full: not a regular file: not replaced$" "$tmp/err"; then
    echo "FAIL: --checkpoint-out /dev/full: $(cat "$tmp/err")"; fails=$((fails + 1))
fi
# Iwan elements (--iwan-params: a line k_1 phi_1 ... k_ns phi_ns per element): four equal
# sliders of 50.0 and 0.0125 N are the slipping Jenkins element of 200.0 and 0.05 N above, to
# rounding; Segalman's model (--iwan-segalman: F_S K_T chi beta) in one slider with beta = 0 is
# the Jenkins element of kt = K_T, mun = F_S exactly (docs/joints.md), and in 50 sliders whose
# stiffnesses sum to K_T with F_S = 1e30 (every slider stuck) the closed form above.
echo "50.0 0.0125 50.0 0.0125 50.0 0.0125 50.0 0.0125" >"$d/I_slip.txt"
echo "0.05 200.0 -0.5 0" >"$d/S_slip.txt"
echo "1e30 200.0 -0.5 0" >"$d/S_stuck.txt"
expect_same 1e-12 $jk --jenkins-params $d/P_slip.txt --integrator newmark -- $jk --iwan-params $d/I_slip.txt --integrator newmark
expect_output '"jenkins_dissipation": 0\.0[0-9]*[1-9][0-9]*, "element_kind": "iwan", "sliders_per_element": 4' $jk --iwan-params $d/I_slip.txt --integrator newmark
expect_same 0 $jk --jenkins-params $d/P_slip.txt --integrator central -- $jk --iwan-segalman $d/S_slip.txt --iwan-sliders 1 --integrator central
expect_output '"x": \[-0\.00113279590437[89][0-9]*\].*"element_kind": "iwan", "sliders_per_element": 50' $jk --iwan-segalman $d/S_stuck.txt --integrator newmark
printf '# k phi\n50.0 0.0125 50.0 0.0125\n200.0 0.05\n' >"$d/I_uneven.txt"
mtx J2e.mtx general "2 1 2" "1 1 1" "2 1 1"
expect_usage_error "^fricreg-sim: --iwan-params $d/I_uneven.txt: line 3: 1 sliders, line 2 has 2: every element needs the same number of sliders" ${jk%% --jenkins *} --jenkins $d/J2e.mtx --iwan-params $d/I_uneven.txt --integrator newmark --dt 0.01 --t-end 1
echo "50.0 0.0125 50.0" >"$d/I_odd.txt"
expect_usage_error "^fricreg-sim: --iwan-params $d/I_odd.txt: line 1: 3 numbers: give pairs" $jk --iwan-params $d/I_odd.txt --integrator newmark
expect_usage_error "^fricreg-sim: --iwan-params $d/nosuch.txt: cannot open" $jk --iwan-params $d/nosuch.txt --integrator newmark
expect_usage_error "^fricreg-sim: --iwan-params: give only one of" $jk --jenkins-params $d/P_slip.txt --iwan-params $d/I_slip.txt --integrator newmark
echo "0.05 200.0 -1 0" >"$d/S_bad.txt"
expect_usage_error "^fricreg-sim: --iwan-segalman $d/S_bad.txt: .*chi" $jk --iwan-segalman $d/S_bad.txt --integrator newmark
# 2-D elements (--jenkins-2d: rows 2i-1, 2i the element's x and y): the oscillator above with a
# second dof (m 1.0, k 100, outside the ground's influence, so at rest), the element's x on dof
# 1 and y on dof 2, is the 1-D element on dof 1 (docs/joints.md: motion on one axis is the 1-D
# element bit for bit), stuck and slipping; stuck, its force [kt x, 0] from the closed form
# above (200.0 x -0.00113279590437900 = -0.2265591808758; printed -0.2265591808757984).
mtx M22.mtx symmetric "2 2 2" "1 1 2.385" "2 2 1.0"
mtx K22.mtx symmetric "2 2 2" "1 1 217.3" "2 2 100.0"
mtx J12.mtx general "1 2 1" "1 1 1"
mtx R2.mtx general "2 1 1" "1 1 1"
mtx J2d.mtx general "2 2 2" "1 1 1" "2 2 1"
jk2="structure --mass $d/M22.mtx --stiffness $d/K22.mtx --contacts $d/J12.mtx --mun $d/mun0.txt --ground-accel $d/ag_osc.txt --influence $d/R2.mtx --dt 0.01 --t-end 1.37"
expect_same 0 $jk2 --jenkins $d/J12.mtx --jenkins-params $d/P_stuck.txt --integrator newmark -- $jk2 --jenkins-2d $d/J2d.mtx --jenkins-params $d/P_stuck.txt --integrator newmark
expect_same 0 $jk2 --jenkins $d/J12.mtx --jenkins-params $d/P_slip.txt --integrator newmark -- $jk2 --jenkins-2d $d/J2d.mtx --jenkins-params $d/P_slip.txt --integrator newmark
expect_same 0 $jk2 --jenkins $d/J12.mtx --jenkins-params $d/P_slip.txt --integrator central -- $jk2 --jenkins-2d $d/J2d.mtx --jenkins-params $d/P_slip.txt --integrator central
expect_output '"x": \[-0\.00113279590437[89][0-9]*, 0\].*"njenkins": 1, "dissipation_per_jenkins": \[0\], "dissipation_per_jenkins_error_estimate": \[0\], "dissipation_per_jenkins_error_kind": \["bound"\], "jenkins_dissipation": 0, "element_kind": "jenkins-2d", "jenkins_forces": \[\[-0\.226559180875(79|80)[0-9]*, 0\]\]' $jk2 --jenkins-2d $d/J2d.mtx --jenkins-params $d/P_stuck.txt --integrator newmark
mtx J2odd.mtx general "3 2 3" "1 1 1" "2 2 1" "3 1 1"
expect_usage_error "^fricreg-sim: --jenkins-2d $d/J2odd.mtx: 3 rows: a 2-D element takes two" $jk2 --jenkins-2d $d/J2odd.mtx --jenkins-params $d/P_stuck.txt --integrator newmark
expect_usage_error "^fricreg-sim: --jenkins-2d: give --jenkins or --jenkins-2d, not both" $jk2 --jenkins $d/J12.mtx --jenkins-2d $d/J2d.mtx --jenkins-params $d/P_stuck.txt --integrator newmark
expect_usage_error "^fricreg-sim: --jenkins-2d: 2-D elements take --jenkins-params or --normal" $jk2 --jenkins-2d $d/J2d.mtx --iwan-params $d/I_slip.txt --integrator newmark
expect_usage_error "^fricreg-sim: --jenkins-params: missing (--jenkins-2d goes with" $jk2 --jenkins-2d $d/J2d.mtx --integrator newmark
expect_usage_error "^fricreg-sim: --jenkins-2d: Jenkins elements are integrated by newmark" $jk2 --jenkins-2d $d/J2d.mtx --jenkins-params $d/P_stuck.txt --integrator rk4
expect_usage_error "^fricreg-sim: --iwan-sliders: only with --iwan-segalman" $jk --iwan-params $d/I_slip.txt --iwan-sliders 3 --integrator newmark
expect_usage_error "^fricreg-sim: --iwan-resolution: must be < 1" $jk --iwan-segalman $d/S_slip.txt --iwan-resolution 1 --integrator newmark
# Lift-off (--normal Jn.mtx --normal-params Q.txt, a line kt mu n0 kn per element): the
# element of kt = 200.0 on dof 1 (the oscillator above, its K2a 217.3) pressed by dof 2
# (m 1.3, k 80) with n0 = 1000 N, kn = 40 N/m, mu = 1e27: stuck and closed (N >= 1000 - 40 x
# 2 x 1000.95/120 = 333 N), so dof 1 is the closed form above, and dof 2 is an undamped
# oscillator of stiffness 80 + 40 under -(n0 + 1.3 A): Newmark's u_2 = -(1000.9503/120)
# (1 - cos(W 1.37 s)), W = (2/dt) atan(w dt/2), w = sqrt(120/1.3): -1.39190163488111 m, and
# N = 1000 + 40 u_2 = 944.323934604756 N.
mtx M2n.mtx symmetric "2 2 2" "1 1 2.385" "2 2 1.3"
mtx K2n.mtx symmetric "2 2 2" "1 1 217.3" "2 2 80"
mtx Jt2.mtx general "1 2 1" "1 1 1"
mtx Jn2.mtx general "1 2 1" "1 2 1"
echo "200.0 1e27 1000 40" >"$d/Q_stuck.txt"
lo="structure --mass $d/M2n.mtx --stiffness $d/K2n.mtx --contacts $d/Jt2.mtx --mun $d/mun0.txt --ground-accel $d/ag_osc.txt --jenkins $d/Jt2.mtx --normal $d/Jn2.mtx --dt 0.01 --t-end 1.37 --integrator newmark"
expect_output '"x": \[-0\.00113279590437[89][0-9]*, -1\.391901634881(0[5-9]|1[0-7])[0-9]*\].*"element_kind": "lift-off", "normal_forces": \[944\.3239346047(5[4-9]|6[0-5])[0-9]*\]' $lo --normal-params $d/Q_stuck.txt
echo "200.0 1e27 1000 0" >"$d/Q_kn0.txt"
expect_usage_error "^fricreg-sim: --normal-params $d/Q_kn0.txt: .*kn > 0" $lo --normal-params $d/Q_kn0.txt
echo "200.0 1e27 1000" >"$d/Q_short.txt"
expect_usage_error "^fricreg-sim: --normal-params $d/Q_short.txt: line 1: expected 4" $lo --normal-params $d/Q_short.txt
expect_usage_error "^fricreg-sim: --normal-params: missing" $lo
expect_usage_error "^fricreg-sim: --normal $d/J2e.mtx: the matrix is 2 x 1" ${lo%% --jenkins *} --jenkins $d/Jt2.mtx --normal $d/J2e.mtx --normal-params $d/Q_stuck.txt --integrator newmark --dt 0.01 --t-end 1
# Iwan elements with lift-off (--iwan-normal-params, a line n0 kn k_1 mu_1 ... per element):
# two stuck sliders of 150 and 50 N/m are the element above, the same closed forms.
echo "1000 40 150 1e27 50 1e27" >"$d/QI_stuck.txt"
expect_output '"x": \[-0\.00113279590437[89][0-9]*, -1\.391901634881(0[5-9]|1[0-7])[0-9]*\].*"element_kind": "iwan-lift-off", "sliders_per_element": 2, "normal_forces": \[944\.3239346047(5[4-9]|6[0-5])[0-9]*\]' $lo --iwan-normal-params $d/QI_stuck.txt
echo "1000 40 150" >"$d/QI_odd.txt"
expect_usage_error "^fricreg-sim: --iwan-normal-params $d/QI_odd.txt: line 1: 3 numbers: give n0 kn, then pairs k_s mu_s" $lo --iwan-normal-params $d/QI_odd.txt
echo "1000 0 150 1e27 50 1e27" >"$d/QI_kn0.txt"
expect_usage_error "^fricreg-sim: --iwan-normal-params $d/QI_kn0.txt: .*kn > 0" $lo --iwan-normal-params $d/QI_kn0.txt
expect_usage_error "^fricreg-sim: --normal: missing (--normal goes with --normal-params or --iwan-normal-params)" ${lo%% --jenkins *} --jenkins $d/Jt2.mtx --iwan-normal-params $d/QI_stuck.txt --integrator newmark --dt 0.01 --t-end 1
expect_usage_error "^fricreg-sim: --iwan-normal-params: give only one of" $lo --normal-params $d/Q_stuck.txt --iwan-normal-params $d/QI_stuck.txt
# 3-D contact elements (--jenkins-2d with --normal and --normal-params: tangential x, y and
# normal n): the lift-off case above (both its dofs shaken by the ground) with a dof at rest
# (m 1.0, k 100, outside the ground's influence) under the element's y row: dof 1 and dof 3 are the closed forms above,
# y stays 0, f = [kt x, 0] and N = 944.323934604756.
mtx M3n.mtx symmetric "3 3 3" "1 1 2.385" "2 2 1.0" "3 3 1.3"
mtx K3n.mtx symmetric "3 3 3" "1 1 217.3" "2 2 100.0" "3 3 80"
mtx Jc3.mtx general "1 3 1" "1 1 1"
mtx R3.mtx general "3 1 2" "1 1 1" "3 1 1"
mtx J2d3.mtx general "2 3 2" "1 1 1" "2 2 1"
mtx Jn3.mtx general "1 3 1" "1 3 1"
c3="structure --mass $d/M3n.mtx --stiffness $d/K3n.mtx --contacts $d/Jc3.mtx --mun $d/mun0.txt --ground-accel $d/ag_osc.txt --influence $d/R3.mtx --jenkins-2d $d/J2d3.mtx --normal $d/Jn3.mtx --dt 0.01 --t-end 1.37 --integrator newmark"
expect_output '"x": \[-0\.00113279590437[89][0-9]*, 0, -1\.391901634881(0[5-9]|1[0-7])[0-9]*\].*"element_kind": "contact-3d", "jenkins_forces": \[\[-0\.226559180875(79|80)[0-9]*, 0\]\], "normal_forces": \[944\.3239346047(5[4-9]|6[0-5])[0-9]*\]' $c3 --normal-params $d/Q_stuck.txt
expect_usage_error "^fricreg-sim: --normal-params $d/Q_kn0.txt: .*kn > 0" $c3 --normal-params $d/Q_kn0.txt
expect_usage_error "^fricreg-sim: --normal-params: missing" $c3
expect_usage_error "^fricreg-sim: --jenkins-2d: 2-D elements take --jenkins-params or --normal" $c3 --iwan-params $d/I_slip.txt

# Element sets of any types in one run (--elements TYPE:J.mtx:P.txt, repeatable, each added by
# fricreg_structure_add_elements in order). es_as_old FILE: a summary with --elements in the
# old options' words (nelements, dissipation_per_element, element_dissipation; the sets' list
# and forces, which the old 1-D summary does not print, dropped), the CPU times dropped.
es_as_old() {
    sed -e 's/"cpu_seconds": [0-9.e+-]*//; s/"companion_cpu_seconds": [0-9.e+-]*//; s/"companion_cpu_share": [0-9.e+-]*//' \
        -e 's/"nelements"/"njenkins"/; s/"dissipation_per_element/"dissipation_per_jenkins/g' \
        -e 's/"element_dissipation"/"jenkins_dissipation"/; s/, "element_sets": \[[^]]*\]//' \
        -e 's/, "element_forces": \[\[[^]]*\]\]//' "$1"
}
# (1) One set is the old option's run: the slipping Jenkins element of the oscillator above
# (--jenkins J1.mtx --jenkins-params P_slip.txt) as --elements jenkins, the same summary to the
# last digit (one structure of one type is the per-kind setter, bit for bit).
"$sim" $jk --jenkins-params $d/P_slip.txt --integrator newmark >"$d/es_old.json" 2>"$tmp/err"
"$sim" ${jk%% --jenkins *} --elements jenkins:$d/J1.mtx:$d/P_slip.txt --dt 0.01 --t-end 1.37 --integrator newmark >"$d/es_new.json" 2>>"$tmp/err"
total=$((total + 1))
es_as_old "$d/es_old.json" >"$d/es_old.txt"
es_as_old "$d/es_new.json" >"$d/es_new.txt"
if ! grep -Eq '"element_kind": "jenkins", "element_sets": \[\{"type": "jenkins", "nelements": 1, "sliders_per_element": 1\}\], "element_forces": \[\[-?[0-9.e-]+\]\]' "$d/es_new.json" ||
   ! grep -q '"dissipation_per_jenkins": \[0\.0[0-9]*[1-9]' "$d/es_old.txt" || ! cmp -s "$d/es_old.txt" "$d/es_new.txt"; then
    echo "FAIL: --elements jenkins is not --jenkins with --jenkins-params: $(head -c 600 "$d/es_new.json") | $(head -c 300 "$d/es_old.json") $(cat "$tmp/err")"; fails=$((fails + 1))
fi
# (2) Two sets of different types: two decoupled copies of that oscillator (dof 2 the same mass
# and spring, on the same ground), the slipping Jenkins element on dof 1 and an Iwan element of
# 3 sliders on dof 2, its line in the kernel's layout (k_1 k_2 k_3 phi_1 phi_2 phi_3, where
# --iwan-params takes pairs). Each element's dissipation is the same element's alone by the old
# options in the same model (dof 1: --jenkins, dof 2: --jenkins with --iwan-params), and the
# energy balance's jenkins entry their sum, to 1e-12 (the one Newton over both elements may
# stop an iteration apart from each one's; equal to the last digit on x86-64 with GCC).
decoupled "" 2.385 217.3 2.385 217.3
echo "100 60 40 0.02 0.03 0.04" >"$d/E_iwan3.txt"
echo "100 0.02 60 0.03 40 0.04" >"$d/I_iwan3.txt"
es="structure --mass $d/M22.mtx --stiffness $d/K22.mtx --contacts $d/J1of2.mtx --mun $d/mun0.txt --ground-accel $d/ag_osc.txt --dt 0.01 --t-end 1.37 --integrator newmark"
"$sim" $es --elements jenkins:$d/J1of2.mtx:$d/P_slip.txt --elements iwan:$d/J2of2.mtx:$d/E_iwan3.txt >"$d/es_mix.json" 2>"$tmp/err"
"$sim" $es --jenkins $d/J1of2.mtx --jenkins-params $d/P_slip.txt >"$d/es_j.json" 2>>"$tmp/err"
"$sim" $es --jenkins $d/J2of2.mtx --iwan-params $d/I_iwan3.txt >"$d/es_i.json" 2>>"$tmp/err"
total=$((total + 1))
per_element=$(sed -n 's/.*"dissipation_per_element": \[\([^]]*\)\].*"jenkins": \([^,]*\),.*/\1, \2/p' "$d/es_mix.json")
alone=$(sed -n 's/.*"dissipation_per_jenkins": \[\([^]]*\)\].*/\1/p' "$d/es_j.json" "$d/es_i.json" | tr '\n' ' ')
if ! grep -Eq '"nelements": 2, .*"element_kind": "mixed", "element_sets": \[\{"type": "jenkins", "nelements": 1, "sliders_per_element": 1\}, \{"type": "iwan", "nelements": 1, "sliders_per_element": 3\}\], "element_forces": \[\[-?[0-9.e-]+\], \[-?[0-9.e-]+\]\]' "$d/es_mix.json" ||
   ! echo "$per_element $alone" | tr -d ',' | awk '{ for (k = 1; k <= 2; k++) { d = $k - $(k + 3); if (d < 0) d = -d; if (!($k > 1e-4 && d <= 1e-12 * $k)) exit 1 }
        d = $3 - $4 - $5; if (d < 0) d = -d; exit !(d <= 1e-12 * $3) }'; then
    echo "FAIL: --elements jenkins and iwan: dissipations $per_element, alone $alone: $(head -c 600 "$d/es_mix.json") $(cat "$tmp/err")"; fails=$((fails + 1))
fi
# --output-elements LIST: the trajectory's columns of the elements listed, in its order: each
# one's forces eI_f.. and its sliders' slips eI_s.. (fricreg_structure_get_elements). On the run
# above with elements 2,1: the Jenkins element's force is kt (u1 - s) and the Iwan element's
# sum_j k_j (u2 - s_j) at every row, each slider's within its slip force, the Jenkins element
# reaching its 0.05 N (it slips), to rounding; the other columns are those of the run without.
"$sim" $es --elements jenkins:$d/J1of2.mtx:$d/P_slip.txt --elements iwan:$d/J2of2.mtx:$d/E_iwan3.txt --output trajectory --output-elements 2,1 >"$d/es_cols.csv" 2>"$tmp/err"
"$sim" $es --elements jenkins:$d/J1of2.mtx:$d/P_slip.txt --elements iwan:$d/J2of2.mtx:$d/E_iwan3.txt --output trajectory >"$d/es_nocols.csv" 2>>"$tmp/err"
total=$((total + 1))
if [ "$(head -n 1 "$d/es_cols.csv")" != "t,u1,u2,v1,v2,f1,e2_f1,e2_s1,e2_s2,e2_s3,e1_f1,e1_s1" ] ||
   [ "$(cut -d, -f1-6 "$d/es_cols.csv" | cksum)" != "$(cksum <"$d/es_nocols.csv")" ] ||
   ! awk -F, 'function abs(x) { return x < 0 ? -x : x }
        NR > 1 { if (abs($11 - 200 * ($2 - $12)) > 1e-12 || abs($11) > 0.05 * (1 + 1e-12)) exit 1
                 split("100 60 40", k, " "); split("0.02 0.03 0.04", phi, " "); sum = 0
                 for (j = 1; j <= 3; j++) { fj = k[j] * ($3 - $(7 + j)); sum += fj
                                            if (abs(fj) > phi[j] * (1 + 1e-12)) exit 1 }
                 if (abs($7 - sum) > 1e-12) exit 1
                 if (abs($11) > top) top = abs($11) }
        END { exit !(NR > 100 && top >= 0.05 * (1 - 1e-12)) }' "$d/es_cols.csv"; then
    echo "FAIL: --output-elements 2,1: $(head -n 3 "$d/es_cols.csv") $(cat "$tmp/err")"; fails=$((fails + 1))
fi
expect_usage_error "^fricreg-sim: --output-elements: element 3 is beyond the model's 2 (the run adds 2 elements)" $es --elements jenkins:$d/J1of2.mtx:$d/P_slip.txt --elements iwan:$d/J2of2.mtx:$d/E_iwan3.txt --output trajectory --output-elements 1,3
expect_usage_error "^fricreg-sim: --output-elements: only --output trajectory" $es --elements jenkins:$d/J1of2.mtx:$d/P_slip.txt --output-elements 1
expect_usage_error "^fricreg-sim: --output-elements: '0' is not an element" $es --elements jenkins:$d/J1of2.mtx:$d/P_slip.txt --output trajectory --output-elements 0
# (3) A type with a normal law: the 3-D contact element above (--jenkins-2d with --normal, its
# line kt mu n0 kn) as --elements contact_3d, its three rows in one matrix and its line in the
# kernel's layout kt mu kn n0 gap: its forces [f_x, f_y, N] are the old run's jenkins_forces and
# normal_forces, its dissipation the old one's, to the last digit.
mtx Jc33.mtx general "3 3 3" "1 1 1" "2 2 1" "3 3 1"
echo "200.0 1e27 40 1000 0" >"$d/E_c3.txt"
"$sim" $c3 --normal-params $d/Q_stuck.txt >"$d/es_c3_old.json" 2>"$tmp/err"
"$sim" ${c3%% --jenkins-2d *} --elements contact_3d:$d/Jc33.mtx:$d/E_c3.txt --dt 0.01 --t-end 1.37 --integrator newmark >"$d/es_c3_new.json" 2>>"$tmp/err"
total=$((total + 1))
old_f=$(sed -n 's/.*"jenkins_forces": \[\[\([^]]*\)\]\], "normal_forces": \[\([^]]*\)\].*/\1, \2/p' "$d/es_c3_old.json")
new_f=$(sed -n 's/.*"element_forces": \[\[\([^]]*\)\]\].*/\1/p' "$d/es_c3_new.json")
if [ -z "$old_f" ] || [ "$old_f" != "$new_f" ] ||
   [ "$(sed -n 's/.*"dissipation_per_jenkins": \(\[[^]]*\]\).*/\1/p' "$d/es_c3_old.json")" != "$(sed -n 's/.*"dissipation_per_element": \(\[[^]]*\]\).*/\1/p' "$d/es_c3_new.json")" ]; then
    echo "FAIL: --elements contact_3d: forces [$new_f], --jenkins-2d --normal's [$old_f] $(cat "$tmp/err")"; fails=$((fails + 1))
fi
# Its usage errors name the option, the file and the line.
echo "200.0 0.05 1" >"$d/E_three.txt"
printf '100 60 40 0.02 0.03 0.04\n# a comment\n100 60 0.02 0.03\n' >"$d/E_uneven.txt"
echo "-1 0.05" >"$d/E_bad.txt"
mtx J3of2.mtx general "3 2 3" "1 1 1" "2 2 1" "3 1 1"
mtx J2rows.mtx general "2 2 2" "1 1 1" "2 2 1"
expect_usage_error "^fricreg-sim: --elements: unknown element type 'jenkin' (jenkins, jenkins_2d, contact_3d, iwan" $es --elements jenkin:$d/J1of2.mtx:$d/P_slip.txt
expect_usage_error "^fricreg-sim: --elements: expected TYPE:J.mtx:P.txt" $es --elements jenkins:$d/J1of2.mtx
expect_usage_error "^fricreg-sim: --elements $d/E_three.txt: line 1: 3 numbers: jenkins takes 2 parameters" $es --elements jenkins:$d/J1of2.mtx:$d/E_three.txt
expect_usage_error "^fricreg-sim: --elements $d/E_three.txt: line 1: 3 numbers: iwan takes 2 ns parameters" $es --elements iwan:$d/J1of2.mtx:$d/E_three.txt
expect_usage_error "^fricreg-sim: --elements $d/E_uneven.txt: line 3: 4 numbers, line 1 has 6: every element of a set takes the same parameters" $es --elements iwan:$d/J2rows.mtx:$d/E_uneven.txt
expect_usage_error "^fricreg-sim: --elements $d/E_bad.txt: line 1: jenkins: kt = -1 must be > 0" $es --elements jenkins:$d/J1of2.mtx:$d/E_bad.txt
expect_usage_error "^fricreg-sim: --elements $d/J3of2.mtx: 3 rows: jenkins_2d takes 2 per element (its components), a multiple of 2" $es --elements jenkins_2d:$d/J3of2.mtx:$d/P_slip.txt
expect_usage_error "^fricreg-sim: --elements $d/P_slip.txt: 1 lines, $d/J2rows.mtx has 2 elements" $es --elements jenkins:$d/J2rows.mtx:$d/P_slip.txt
expect_usage_error "^fricreg-sim: --elements: give --elements or the element options" $es --elements jenkins:$d/J1of2.mtx:$d/P_slip.txt --jenkins $d/J2of2.mtx --jenkins-params $d/P_slip.txt
expect_usage_error "^fricreg-sim: --elements: elements are integrated by newmark, hht or central only" ${es%% --integrator *} --integrator rk4 --elements jenkins:$d/J1of2.mtx:$d/P_slip.txt

# Two storeys (m 1.7, 2.3 kg; k 311, 187 N/m), a damper on each drift, a shaken ground:
# symmetric storage (lower triangle) and the full general matrix are the same model, and
# Rayleigh damping given as a0,a1 the same as C = a0 M + a1 K given as a file.
mtx M3.mtx symmetric "2 2 2" "1 1 1.7" "2 2 2.3"
mtx K3s.mtx symmetric "2 2 3" "1 1 498" "2 1 -187" "2 2 187"
mtx K3g.mtx general "2 2 4" "1 1 498" "1 2 -187" "2 1 -187" "2 2 187"
mtx C3.mtx symmetric "2 2 3" "1 1 1.6958" "2 1 -0.5797" "2 2 0.8487"
mtx J3.mtx general "2 2 3" "1 1 1" "2 1 -1" "2 2 1"
mtx R3.mtx general "2 1 2" "1 1 1" "2 1 1"
printf '0.93\n0.41\n' >"$d/mun3.txt"
awk 'BEGIN { for (k = 0; k <= 400; k++) printf "%.2f %.17g\n", k * 0.01, 3.1 * sin(5.3 * k * 0.01) }' >"$d/ag3.txt"
two="--mass $d/M3.mtx --contacts $d/J3.mtx --mun $d/mun3.txt --ground-accel $d/ag3.txt --influence $d/R3.mtx --eps 0.003 --integrator newmark --dt 0.004 --t-end 4"
# a0 = 0.4, a1 = 0.0031: C = 0.4 M + 0.0031 K = [[1.6838, -0.5797], [-0.5797, 1.4997]]
mtx C3.mtx symmetric "2 2 3" "1 1 2.2238" "2 1 -0.5797" "2 2 1.4997"
"$sim" structure $two --stiffness "$d/K3s.mtx" --rayleigh 0.4,0.0031 >"$d/sym.json" 2>&1
"$sim" structure $two --stiffness "$d/K3g.mtx" --rayleigh 0.4,0.0031 >"$d/gen.json" 2>&1
"$sim" structure $two --stiffness "$d/K3s.mtx" --damping "$d/C3.mtx" >"$d/damp.json" 2>&1
total=$((total + 2))
field() { sed -e 's/.*"dissipation_per_contact": \[\([^]]*\)\].*/\1/' "$1"; }
if [ -z "$(field "$d/sym.json")" ] || [ "$(field "$d/sym.json")" != "$(field "$d/gen.json")" ]; then
    echo "FAIL: symmetric and general storage differ: $(cat "$d/sym.json" "$d/gen.json")"; fails=$((fails + 1))
fi
if ! awk -v a="$(field "$d/sym.json")" -v b="$(field "$d/damp.json")" 'BEGIN {
        n = split(a, x, ", "); split(b, y, ", "); if (n != 2) exit 1
        for (i = 1; i <= n; i++) { e = (x[i] - y[i]) / y[i]; if (e < -1e-9 || e > 1e-9 || y[i] <= 0) exit 1 } }'; then
    echo "FAIL: --rayleigh and --damping differ: $(cat "$d/sym.json" "$d/damp.json")"; fails=$((fails + 1))
fi
# Trajectory: a header and a row per step plus t = 0 (4/0.004 = 1000 steps).
total=$((total + 1))
"$sim" structure $two --stiffness "$d/K3s.mtx" --output trajectory >"$d/traj.csv" 2>&1
if [ "$(head -n 1 "$d/traj.csv")" != "t,u1,u2,v1,v2,f1,f2" ] || [ "$(wc -l <"$d/traj.csv")" -ne 1002 ]; then
    echo "FAIL: structure trajectory: $(head -n 2 "$d/traj.csv"), $(wc -l <"$d/traj.csv") lines"; fails=$((fails + 1))
fi

# --output-dofs LIST and --output-every K: the columns of the dofs listed, in its order, and the
# rows at the steps k dt with k a multiple of K plus the last: 0, 7, ..., 994 and 1000, 144
# rows, each the full trajectory's; the summary's per-dof arrays the same dofs, named.
"$sim" structure $two --stiffness "$d/K3s.mtx" --output trajectory --output-dofs 2 --output-every 7 >"$d/traj_sel.csv" 2>&1
total=$((total + 1))
awk -F, 'NR == 1 || (NR - 2) % 7 == 0 || NR == 1002 { print $1 "," $3 "," $5 "," $6 "," $7 }' "$d/traj.csv" >"$d/traj_cut.csv"
if [ "$(head -n 1 "$d/traj_sel.csv")" != "t,u2,v2,f1,f2" ] || [ "$(wc -l <"$d/traj_sel.csv")" -ne 145 ] ||
   ! cmp -s "$d/traj_sel.csv" "$d/traj_cut.csv"; then
    echo "FAIL: structure --output-dofs 2 --output-every 7: $(head -n 2 "$d/traj_sel.csv"), $(wc -l <"$d/traj_sel.csv") lines"; fails=$((fails + 1))
fi
x_of() { grep '^{' "$1" | sed -e 's/.*"x": \[\([^]]*\)\].*"peak_displacement": \[\([^]]*\)\].*/\1 \2/' -e 's/,//g'; }
"$sim" structure $two --stiffness "$d/K3s.mtx" --rayleigh 0.4,0.0031 --output-dofs 2,1 >"$d/sel.json" 2>/dev/null
total=$((total + 1))
if ! grep -q '"output_dofs": \[2, 1\], "x": ' "$d/sel.json" ||
   [ "$(x_of "$d/sel.json" | awk '{ print $2, $1, $4, $3 }')" != "$(x_of "$d/sym.json")" ]; then
    echo "FAIL: structure --output-dofs 2,1: $(head -c 400 "$d/sel.json")"; fails=$((fails + 1))
fi
expect_usage_error "^fricreg-sim: --output-dofs: dof 3 is beyond the model's 2" structure $two --stiffness "$d/K3s.mtx" --output-dofs 1-3
expect_usage_error "^fricreg-sim: --output-dofs: dof 2 is named twice" structure $two --stiffness "$d/K3s.mtx" --output-dofs 1-2,2
expect_usage_error "^fricreg-sim: --output-dofs: range '2-1' runs backwards" structure $two --stiffness "$d/K3s.mtx" --output-dofs 2-1
expect_usage_error "^fricreg-sim: --output-dofs: '1x' is not a dof" structure $two --stiffness "$d/K3s.mtx" --output-dofs 1x
expect_usage_error "^fricreg-sim: --output-dofs: '' is not a dof" structure $two --stiffness "$d/K3s.mtx" --output-dofs 1,
# --output-contacts LIST or none: the force columns of the contacts listed, in its order (the
# full trajectory's), or none: 21 columns for 10 dofs, as on the big model of structural.md.
"$sim" structure $two --stiffness "$d/K3s.mtx" --output trajectory --output-contacts 2 >"$d/traj_c2.csv" 2>&1
"$sim" structure $two --stiffness "$d/K3s.mtx" --output trajectory --output-dofs 1 --output-contacts none >"$d/traj_c0.csv" 2>&1
total=$((total + 1))
awk -F, '{ print $1 "," $2 "," $3 "," $4 "," $5 "," $7 }' "$d/traj.csv" >"$d/traj_c2_cut.csv"
awk -F, '{ print $1 "," $2 "," $4 }' "$d/traj.csv" >"$d/traj_c0_cut.csv"
if [ "$(head -n 1 "$d/traj_c2.csv")" != "t,u1,u2,v1,v2,f2" ] || ! cmp -s "$d/traj_c2.csv" "$d/traj_c2_cut.csv" ||
   [ "$(head -n 1 "$d/traj_c0.csv")" != "t,u1,v1" ] || ! cmp -s "$d/traj_c0.csv" "$d/traj_c0_cut.csv"; then
    echo "FAIL: structure --output-contacts 2 / none: $(head -n 2 "$d/traj_c2.csv") / $(head -n 2 "$d/traj_c0.csv")"; fails=$((fails + 1))
fi
expect_usage_error "^fricreg-sim: --output-contacts: contact 3 is beyond the model's 2 (--contacts has 2 rows)" structure $two --stiffness "$d/K3s.mtx" --output trajectory --output-contacts 3
expect_usage_error "^fricreg-sim: --output-contacts: 'nothing' is not a contact" structure $two --stiffness "$d/K3s.mtx" --output trajectory --output-contacts nothing
expect_usage_error "^fricreg-sim: --output-contacts: only --output trajectory" structure $two --stiffness "$d/K3s.mtx" --output-contacts 1
expect_usage_error "^fricreg-sim: --output-every: must be a whole number" structure $two --stiffness "$d/K3s.mtx" --output trajectory --output-every 0
expect_usage_error "^fricreg-sim: --output-every: only --output trajectory" structure $two --stiffness "$d/K3s.mtx" --output-every 2

# Bad files: one line naming the option, the file and the line or entry; exit 2, no stdout.
ok="--stiffness $d/K3s.mtx --contacts $d/J3.mtx --mun $d/mun3.txt --integrator newmark --dt 0.01 --t-end 1"
printf '2 2 1\n1 1 1\n' >"$d/nobanner.mtx"
mtx array.mtx general "2 2" && sed -i 's/coordinate/array/' "$d/array.mtx"
mtx complex.mtx general "1 1 1" "1 1 1 2" && sed -i 's/real/complex/' "$d/complex.mtx"
mtx range.mtx symmetric "2 2 2" "1 1 1.7" "3 1 2.3"
mtx nan.mtx symmetric "2 2 2" "1 1 1.7" "2 2 nan"
mtx short.mtx symmetric "2 2 3" "1 1 1.7" "2 2 2.3"
mtx twice.mtx symmetric "2 2 3" "1 1 1.7" "2 2 2.3" "1 1 1.7"
mtx upper.mtx symmetric "2 2 3" "1 1 1.7" "1 2 0.1" "2 2 2.3"
mtx singular.mtx symmetric "2 2 1" "1 1 1.7"
mtx asym.mtx general "2 2 4" "1 1 498" "1 2 -187" "2 1 -186" "2 2 187"
mtx K33.mtx symmetric "3 3 3" "1 1 1" "2 2 1" "3 3 1"
mtx J13.mtx general "1 3 1" "1 1 1"
mtx Jzero.mtx general "2 2 1" "1 1 1"
expect_usage_error "^fricreg-sim: --mass $d/none.mtx: cannot open" structure --mass "$d/none.mtx" $ok
expect_usage_error "^fricreg-sim: --mass $d/nobanner.mtx: line 1: not a Matrix Market file" structure --mass "$d/nobanner.mtx" $ok
expect_usage_error "^fricreg-sim: --mass $d/array.mtx: line 1: 'matrix array'" structure --mass "$d/array.mtx" $ok
expect_usage_error "^fricreg-sim: --mass $d/complex.mtx: line 1: field 'complex'" structure --mass "$d/complex.mtx" $ok
expect_usage_error "^fricreg-sim: --mass $d/range.mtx: line 5: expected 'row column value' with a row from 1 to 2" structure --mass "$d/range.mtx" $ok
expect_usage_error "^fricreg-sim: --mass $d/nan.mtx: line 5: .*finite value" structure --mass "$d/nan.mtx" $ok
expect_usage_error "^fricreg-sim: --mass $d/short.mtx: 2 entries, the size line says 3" structure --mass "$d/short.mtx" $ok
expect_usage_error "^fricreg-sim: --mass $d/twice.mtx: line 6: entry (1, 1) given twice" structure --mass "$d/twice.mtx" $ok
expect_usage_error "^fricreg-sim: --mass $d/upper.mtx: line 5: entry (1, 2) above the diagonal" structure --mass "$d/upper.mtx" $ok
expect_usage_error "^fricreg-sim: --mass $d/singular.mtx: the mass matrix is singular" structure --mass "$d/singular.mtx" $ok
expect_usage_error "^fricreg-sim: --stiffness $d/asym.mtx: not symmetric: entry (2, 1) = -186 but (1, 2) = -187$" structure --mass "$d/M3.mtx" --stiffness "$d/asym.mtx" --contacts $d/J3.mtx --mun $d/mun3.txt --integrator newmark --dt 0.01 --t-end 1
expect_usage_error "^fricreg-sim: --stiffness $d/K33.mtx: the matrix is 3 x 3, expected 2 x 2$" structure --mass "$d/M3.mtx" --stiffness "$d/K33.mtx" --contacts $d/J3.mtx --mun $d/mun3.txt --integrator newmark --dt 0.01 --t-end 1
expect_usage_error "^fricreg-sim: --contacts $d/J13.mtx: the matrix is 1 x 3, expected 1 x 2$" structure --mass "$d/M3.mtx" --stiffness "$d/K3s.mtx" --contacts $d/J13.mtx --mun $d/mun3.txt --integrator newmark --dt 0.01 --t-end 1
# A mass matrix whose size line says 3 x 3 while its entries end at 2 x 2 is that file's fault,
# not that of the 2 x 2 stiffness or 2-column contacts read against its n = 3: named there, at
# its size line (line 3). A 3 x 3 stiffness against a 2 x 2 mass stays the stiffness's (above).
mtx M3big.mtx symmetric "3 3 2" "1 1 1.7" "2 2 2.3"
expect_usage_error "^fricreg-sim: --mass $d/M3big.mtx: line 3: the size line says 3 x 3, but no entry is beyond row and column 2, and --stiffness $d/K3s.mtx is 2 x 2$" structure --mass "$d/M3big.mtx" $ok
expect_usage_error "^fricreg-sim: --mass $d/M3big.mtx: line 3: the size line says 3 x 3, but no entry is beyond row and column 2, and --contacts $d/J3.mtx is 2 x 2$" structure --mass "$d/M3big.mtx" --stiffness "$d/K33.mtx" --contacts $d/J3.mtx --mun $d/mun3.txt --integrator newmark --dt 0.01 --t-end 1
expect_usage_error "^fricreg-sim: --contacts $d/Jzero.mtx: row 2 is zero" structure --mass "$d/M3.mtx" --stiffness "$d/K3s.mtx" --contacts $d/Jzero.mtx --mun $d/mun3.txt --integrator newmark --dt 0.01 --t-end 1
expect_usage_error "^fricreg-sim: --mun $d/mun1.txt: 1 bounds, $d/J3.mtx has 2 contacts" structure --mass "$d/M3.mtx" --stiffness "$d/K3s.mtx" --contacts $d/J3.mtx --mun $d/mun1.txt --integrator newmark --dt 0.01 --t-end 1
printf '0.93\n-0.41\n' >"$d/munneg.txt"
printf '0.93\n0.41 x\n' >"$d/munbad.txt"
expect_usage_error "^fricreg-sim: --mun $d/munneg.txt: bound 2 = -0.41 must be >= 0" structure --mass "$d/M3.mtx" --stiffness "$d/K3s.mtx" --contacts $d/J3.mtx --mun $d/munneg.txt --integrator newmark --dt 0.01 --t-end 1
expect_usage_error "^fricreg-sim: --mun $d/munbad.txt: line 2: " structure --mass "$d/M3.mtx" --stiffness "$d/K3s.mtx" --contacts $d/J3.mtx --mun $d/munbad.txt --integrator newmark --dt 0.01 --t-end 1
printf '0 1\n0.01 2\n0.025 3\n0.03 4\n' >"$d/ag_uneven.txt"
printf '0 1\n' >"$d/ag_one.txt"
good="--mass $d/M3.mtx $ok"
expect_usage_error "^fricreg-sim: --ground-accel $d/ag_uneven.txt: sample 3: t = 0.025" structure $good --ground-accel "$d/ag_uneven.txt"
expect_usage_error "^fricreg-sim: --ground-accel $d/ag_one.txt: 1 samples" structure $good --ground-accel "$d/ag_one.txt"
expect_usage_error "^fricreg-sim: --influence $d/R3.mtx: the matrix is 2 x 1, expected 1 x 1" structure --mass $d/M1.mtx --stiffness $d/K0.mtx --contacts $d/J1.mtx --mun $d/mun1.txt --influence $d/R3.mtx --integrator newmark --dt 0.01 --t-end 1
# Bad options.
expect_usage_error "--mass" structure $ok
base="--mass $d/M3.mtx --stiffness $d/K3s.mtx --contacts $d/J3.mtx --mun $d/mun3.txt"
expect_usage_error "newmark, hht, central, rk2, rk4" structure $base --dt 0.01 --t-end 1 --integrator verlet
# "central" is the structure's own central differences: listed once, not again as a stepper.
total=$((total + 1))
"$sim" structure $base --dt 0.01 --t-end 1 --integrator verlet >/dev/null 2>"$tmp/err"
if [ "$(grep -o 'central' "$tmp/err" | wc -l)" -ne 1 ] || ! grep -q 'msbdf, rk4-gsl)$' "$tmp/err"; then
    echo "FAIL: structure's integrators not each named once: $(cat "$tmp/err")"; fails=$((fails + 1))
fi
expect_usage_error "--rayleigh" structure $good --damping "$d/C3.mtx" --rayleigh 0.4,0.0031
expect_usage_error "--rayleigh" structure $good --rayleigh 0.4
expect_usage_error "--rayleigh" structure $good --rayleigh 0.4,-1
expect_usage_error "--alpha" structure $good --alpha -0.1
expect_usage_error "^fricreg-sim: --alpha: .*alpha = -0.5 must be in \[-1/3, 0\]" structure $base --dt 0.01 --t-end 1 --integrator hht --alpha -0.5
expect_usage_error "--rtol" structure $good --rtol 1e-6
expect_usage_error "--t-end" structure --mass $d/M3.mtx --stiffness $d/K3s.mtx --contacts $d/J3.mtx --mun $d/mun3.txt --integrator newmark --dt 0.01
expect_usage_error "--eps" structure $good --eps 0
expect_usage_error "^fricreg-sim: --dt: more than 2^31 steps" structure $base --integrator newmark --dt 1e-12 --t-end 1

# The reader keeps files sparse (src/cli/matrix_market.c): symmetric storage goes to the
# library as its lower triangle, a general file whole, and the two give the same run to the
# last bit: a consistent M, K and C of three storeys, each in both storages, entries shuffled.
mtx Mc.mtx symmetric "3 3 5" "3 3 2.1" "2 1 0.31" "1 1 1.7" "3 2 0.27" "2 2 2.3"
mtx Mcg.mtx general "3 3 7" "2 2 2.3" "1 2 0.31" "3 3 2.1" "2 1 0.31" "1 1 1.7" "3 2 0.27" "2 3 0.27"
mtx Kc.mtx symmetric "3 3 5" "3 2 -143" "1 1 498" "3 3 143" "2 2 330" "2 1 -187"
mtx Kcg.mtx general "3 3 7" "2 3 -143" "3 2 -143" "2 2 330" "1 2 -187" "3 3 143" "1 1 498" "2 1 -187"
mtx Cc.mtx symmetric "3 3 5" "1 1 1.6958" "2 1 -0.5797" "2 2 1.1" "3 2 -0.4" "3 3 0.7"
mtx Ccg.mtx general "3 3 7" "3 3 0.7" "2 3 -0.4" "3 2 -0.4" "1 2 -0.5797" "2 2 1.1" "2 1 -0.5797" "1 1 1.6958"
mtx Jc.mtx general "2 3 3" "2 3 1" "1 1 1" "2 2 -1"
printf '0.93\n0.41\n' >"$d/munc.txt"
three="--contacts $d/Jc.mtx --mun $d/munc.txt --ground-accel $d/ag3.txt --eps 0.003 --integrator newmark --dt 0.004 --t-end 4"
"$sim" structure --mass "$d/Mc.mtx" --stiffness "$d/Kc.mtx" --damping "$d/Cc.mtx" $three >"$d/lower.json" 2>&1
"$sim" structure --mass "$d/Mcg.mtx" --stiffness "$d/Kcg.mtx" --damping "$d/Ccg.mtx" $three >"$d/whole.json" 2>&1
total=$((total + 1))
same_run() { sed -e 's/"cpu_seconds": [0-9.]*//; s/"companion_cpu_seconds": [0-9.]*//; s/"companion_cpu_share": [0-9.e+-]*//' "$1"; }
if ! grep -q '"ndof": 3, "ncontacts": 2' "$d/lower.json" || [ "$(same_run "$d/lower.json")" != "$(same_run "$d/whole.json")" ]; then
    echo "FAIL: a lower triangle and the whole matrix differ: $(cat "$d/lower.json" "$d/whole.json")"; fails=$((fails + 1))
fi
# A duplicate is found after the sort by column, and named with its line when no bad line
# comes before it (the banner, a comment and the size line are lines 1-3).
mtx dup.mtx general "3 3 6" "3 1 0.5" "1 1 1" "2 2 1" "3 3 1" "3 1 0.25" "2 2 nan"
mtx nandup.mtx general "3 3 6" "3 1 0.5" "1 1 1" "2 2 nan" "3 3 1" "3 1 0.25" "1 1 2"
expect_usage_error "^fricreg-sim: --stiffness $d/dup.mtx: line 8: entry (3, 1) given twice$" structure --mass $d/Mc.mtx --stiffness $d/dup.mtx $three
expect_usage_error "^fricreg-sim: --stiffness $d/nandup.mtx: line 6: expected 'row column value'" structure --mass $d/Mc.mtx --stiffness $d/nandup.mtx $three
# A file of 10^4 entries: a free chain of 5001 storeys (K 1 = 0: it moves as one rigid body),
# its lower triangle written backwards (each column's rows out of order), under a constant
# ground acceleration of 2.41 m/s^2 without friction: every storey at -2.41 T^2/2 = -5.31405 m
# after T = 2.1 s, Newmark being exact for a constant acceleration.
awk 'BEGIN { n = 5001; print "%%MatrixMarket matrix coordinate real symmetric"
    print n, n, 2 * n - 1
    for (i = n; i >= 1; i--) { print i, i, (i == 1 || i == n) ? 1000 : 2000; if (i > 1) print i, i - 1, -1000 } }' >"$d/Kbig.mtx"
awk 'BEGIN { n = 5001; print "%%MatrixMarket matrix coordinate real symmetric"; print n, n, n
    for (i = 1; i <= n; i++) print i, i, 2.5 }' >"$d/Mbig.mtx"
mtx Jbig.mtx general "1 5001 1" "1 1 1"
expect_output '"ndof": 5001, "ncontacts": 1, "x": \[-5\.3140(4999999|5000000)[0-9]*, .*, -5\.3140(4999999|5000000)[0-9]*\], "v"' structure --mass "$d/Mbig.mtx" --stiffness "$d/Kbig.mtx" --contacts "$d/Jbig.mtx" --mun "$d/mun0.txt" --ground-accel "$d/ag_const.txt" --integrator newmark --dt 0.01 --t-end 2.1

# ---- hb: harmonic balance with Jenkins elements (fricreg_hb.h) from Matrix Market files.
# One mass m = 2 on a spring k = 3 and a Jenkins element kt = 1.5 whose slider never slips
# (mu N = 1e6): a linear oscillator of stiffness k + kt = 4.5, Rayleigh C = 0.02 K = 0.06, forced
# by 0.5 cos(Omega t). Its RMS over a period is |X|/sqrt(2) with
# |X| = 0.5/sqrt((4.5 - 2 Omega^2)^2 + (0.06 Omega)^2) (closed form): every row of --output frf
# within 1e-8, every row stable (its Floquet exponents' real part is -c/(2m) = -0.015) with no
# bifurcation, and the summary's peak (located, fricreg_hb_peak) where d|X|/dOmega = 0,
# Omega^2 = (4.5 - 0.06^2/4)/2, Omega = 1.49984999250, RMS 3.92856743987, both within 1e-8.
d=$tmp/hb
mkdir -p "$d"
printf '%s\n' "%%MatrixMarket matrix coordinate real symmetric" "1 1 1" "1 1 2" >"$d/M.mtx"
printf '%s\n' "%%MatrixMarket matrix coordinate real symmetric" "1 1 1" "1 1 3" >"$d/K.mtx"
printf '%s\n' "%%MatrixMarket matrix coordinate real general" "1 1 1" "1 1 1" >"$d/J.mtx"
echo "0.5 0" >"$d/F.txt"
echo "1.5 1e6" >"$d/P.txt"
echo "1.5" >"$d/P1.txt"
hb="hb --mass $d/M.mtx --stiffness $d/K.mtx --rayleigh 0,0.02 --excitation $d/F.txt --jenkins $d/J.mtx --jenkins-params $d/P.txt --harmonics 3 --omega-start 0.5 --omega-end 3"
# hb reads its stiffness against the mass matrix's n as structure does: a mass file whose size
# line says 2 x 2 over one entry is named at its size line (line 2), not the 1 x 1 stiffness.
printf '%s\n' "%%MatrixMarket matrix coordinate real symmetric" "2 2 1" "1 1 2" >"$d/M2big.mtx"
expect_usage_error "^fricreg-sim: --mass $d/M2big.mtx: line 2: the size line says 2 x 2, but no entry is beyond row and column 1, and --stiffness $d/K.mtx is 1 x 1$" hb --mass $d/M2big.mtx --stiffness $d/K.mtx --rayleigh 0,0.02 --excitation $d/F.txt --jenkins $d/J.mtx --jenkins-params $d/P.txt --omega-start 0.5 --omega-end 3
total=$((total + 1))
"$sim" $hb --output frf >"$d/frf.csv" 2>"$d/err"
# The element never slips (mu N = 1e6): the closed forms of the linear oscillator m = 2, k = 4.5,
# c = 0.02 * 3; its Floquet multipliers e^{(-c/2m +- i w_d) 2 pi/omega}, |mu| = e^{-0.015 * 2 pi/omega}
# (by the exact monodromy, the automatic choice for a Jenkins element).
if [ "$(head -n 1 "$d/frf.csv")" != "omega,rms_1,stable,bifurcation,mu_max" ] || ! awk -F, 'NR > 1 { w = $1; a = 4.5 - 2 * w * w; c = 0.06 * w
        r = 0.5 / sqrt(a * a + c * c) / sqrt(2); e = ($2 - r) / r; if (e < 0) e = -e; if (e > big) big = e; rows++
        m = exp(-0.015 * 2 * 3.14159265358979 / w); e = ($5 - m) / m; if (e < 0) e = -e; if (e > bigm) bigm = e
        if ($3 != "1" || $4 != "") bad++ }
        END { exit !(rows >= 20 && big < 1e-8 && bigm < 1e-12 && w == 3 && !bad) }' "$d/frf.csv"; then
    echo "FAIL: hb frf against the linear closed form: $(head -n 3 "$d/frf.csv") $(cat "$d/err")"; fails=$((fails + 1))
fi
# --stability: Hill's method the same verdict and multiplier (no slip: its Jacobian is the
# oscillator's), off no column, the method named in the summary
total=$((total + 1))
"$sim" $hb --output frf --stability hill >"$d/frf_hill.csv" 2>"$d/err"
"$sim" $hb --output frf --stability off >"$d/frf_off.csv" 2>>"$d/err"
"$sim" $hb --stability hill >"$d/summary_hill.json" 2>>"$d/err"
if ! paste -d, "$d/frf.csv" "$d/frf_hill.csv" | awk -F, 'NR > 1 { e = ($5 - $10) / $5; if (e < 0) e = -e; if (e > big) big = e; rows++
        if ($3 != $8) bad++ } END { exit !(rows >= 20 && big < 1e-8 && !bad) }' ||
        ! awk -F, 'NR > 1 && ($3 != "" || $5 != "") { bad++ } END { exit !(NR > 20 && !bad) }' "$d/frf_off.csv" ||
        ! grep -q '"stability_method": "hill"' "$d/summary_hill.json"; then
    echo "FAIL: hb --stability hill/off: $(head -n 3 "$d/frf_hill.csv" "$d/frf_off.csv") $(cat "$d/err")"; fails=$((fails + 1))
fi
expect_usage_error "^fricreg-sim: --stability: " $hb --stability sometimes
total=$((total + 1))
"$sim" $hb >"$d/summary.json" 2>"$d/err"
if ! grep -q '"peaks": "located"' "$d/summary.json" || ! grep -q '"bifurcations": \[\]' "$d/summary.json" ||
        ! grep -q '"stability_method": "monodromy"' "$d/summary.json" ||
        ! sed 's/.*"peak_rms": \([^,]*\), "peak_omega": \([^}]*\)}.*/\1 \2/' "$d/summary.json" |
        awk '{ r = $1 / 3.92856743987 - 1; w = $2 / 1.49984999250 - 1
            exit !(r < 1e-8 && r > -1e-8 && w < 1e-8 && w > -1e-8) }'; then
    echo "FAIL: hb summary peak: $(cat "$d/summary.json" "$d/err")"; fails=$((fails + 1))
fi
# The peak's truncation error estimate (fricreg_hb_truncation_error at the largest stored point):
# rounding where the slider sticks (the response is the linear one, a single harmonic); with
# mu N = 0.1 it slips, and the estimate at H = 3 bounds the peak RMS's difference from H = 19's
# (whose own error is far smaller: the errors fall as about H^-3.5) and is within 10 times it;
# null beyond H = 19 (2H + 1 > 40 harmonics).
echo "1.5 0.1" >"$d/Pslip.txt"
total=$((total + 1))
if ! grep -q '"peak_rms_error_estimate": \[[0-9.e-]*\]' "$d/summary.json" ||
        ! sed 's/.*"peak_rms_error_estimate": \[\([^]]*\)\].*/\1/' "$d/summary.json" |
        awk '{ exit !($1 >= 0 && $1 < 1e-9) }'; then
    echo "FAIL: hb summary's error estimate, stuck: $(cat "$d/summary.json" "$d/err")"; fails=$((fails + 1))
fi
total=$((total + 1))
slip="${hb%% --jenkins-params *} --jenkins-params $d/Pslip.txt --omega-start 0.5 --omega-end 3"
"$sim" $slip --harmonics 3 >"$d/slip3.json" 2>"$d/err"
"$sim" $slip --harmonics 19 >"$d/slip19.json" 2>>"$d/err"
"$sim" $slip --harmonics 20 >"$d/slip20.json" 2>>"$d/err"
if ! { sed 's/.*"peak_rms": \([^,]*\),.*"peak_rms_error_estimate": \[\([^]]*\)\].*/\1 \2/' "$d/slip3.json"
        sed 's/.*"peak_rms": \([^,]*\),.*/\1/' "$d/slip19.json"; } |
        awk 'NR == 1 { r = $1; e = $2 } NR == 2 { t = r - $1; if (t < 0) t = -t
            exit !(t > 1e-6 && e >= t && e <= 10 * t) }' ||
        ! grep -q '"peak_rms_error_estimate": \[null\]' "$d/slip20.json"; then
    echo "FAIL: hb summary's error estimate, slipping: $(cat "$d/slip3.json" "$d/slip19.json" "$d/slip20.json" "$d/err")"; fails=$((fails + 1))
fi
# The step control's options reach the driver: a finer one, the same peak; bad values exit 2;
# a bound of 5 points stops the continuation (exit 1)
total=$((total + 1))
"$sim" $hb --ds 0.005 --ds-min 1e-5 --ds-max 0.01 --max-points 1000 >"$d/fine.json" 2>"$d/err"
if ! sed 's/.*"points": \([0-9]*\),.*"peak_rms": \([^,]*\), "peak_omega": \([^}]*\)}.*/\1 \2 \3/' "$d/fine.json" |
        awk '{ r = $2 / 3.92856743987 - 1; w = $3 / 1.49984999250 - 1
            exit !($1 > 100 && r < 1e-8 && r > -1e-8 && w < 1e-8 && w > -1e-8) }'; then
    echo "FAIL: hb --ds 0.005 --ds-max 0.01: $(cat "$d/fine.json" "$d/err")"; fails=$((fails + 1))
fi
expect_usage_error "^fricreg-sim: --ds: .*ds_max" $hb --ds 0.5
expect_usage_error "^fricreg-sim: --ds-min: must be > 0" $hb --ds-min 0
expect_usage_error "^fricreg-sim: --ds-min: .*ds_min = 0.05" $hb --ds-min 0.05
expect_usage_error "^fricreg-sim: --ds-max: .*ds_max = 2" $hb --ds-max 2
expect_usage_error "^fricreg-sim: --max-points: " $hb --max-points 1
total=$((total + 1))
if "$sim" $hb --max-points 5 >"$d/five.json" 2>"$d/err" || [ $? -ne 1 ] || [ -s "$d/five.json" ] ||
        ! grep -q "5 points stored before" "$d/err"; then
    echo "FAIL: hb --max-points 5: $(cat "$d/five.json" "$d/err")"; fails=$((fails + 1))
fi
# --max-seconds: 0 stops at the first Newton step whatever the machine's speed (the monotonic
# clock never runs back), exit 1, one line naming the option, nothing on stdout; a limit far
# above the run's need gives the unlimited run's summary but its CPU time; a negative one is
# refused.
total=$((total + 1))
if "$sim" $hb --max-seconds 0 >"$d/stopped.json" 2>"$d/err" || [ $? -ne 1 ] || [ -s "$d/stopped.json" ] ||
        ! grep -q "^fricreg-sim: hb: --max-seconds 0 passed: stopped (the continuation from omega = 0.5 had reached 0 points)$" "$d/err"; then
    echo "FAIL: hb --max-seconds 0: $(cat "$d/stopped.json" "$d/err")"; fails=$((fails + 1))
fi
total=$((total + 1))
"$sim" $hb >"$d/unlimited.json" 2>"$d/err"
"$sim" $hb --max-seconds 1e6 >"$d/limited.json" 2>>"$d/err"
if [ "$(sed 's/, "cpu_seconds".*//' "$d/unlimited.json")" != "$(sed 's/, "cpu_seconds".*//' "$d/limited.json")" ] ||
        [ ! -s "$d/limited.json" ]; then
    echo "FAIL: hb --max-seconds 1e6 changed the summary: $(cat "$d/limited.json" "$d/err")"; fails=$((fails + 1))
fi
expect_usage_error "^fricreg-sim: --max-seconds: must be >= 0" $hb --max-seconds -1
# --continue-in level: the same oscillator at Omega = 1.2, the level L from 0.5 to 2: linear,
# every row's RMS L times the closed form's at Omega = 1.2 within 1e-8; the summary's peak the
# last point's (level 2); the frequency options do not apply, the level's are required.
lv="hb --mass $d/M.mtx --stiffness $d/K.mtx --rayleigh 0,0.02 --excitation $d/F.txt --jenkins $d/J.mtx --jenkins-params $d/P.txt --harmonics 3 --continue-in level --omega 1.2"
total=$((total + 1))
"$sim" $lv --level-start 0.5 --level-end 2 --output frf >"$d/level.csv" 2>"$d/err"
if [ "$(head -n 1 "$d/level.csv")" != "level,rms_1,stable,bifurcation,mu_max" ] || ! awk -F, 'NR > 1 { l = $1; w = 1.2; a = 4.5 - 2 * w * w; c = 0.06 * w
        r = l * 0.5 / sqrt(a * a + c * c) / sqrt(2); e = ($2 - r) / r; if (e < 0) e = -e; if (e > big) big = e; rows++
        if ($3 != "1" || $4 != "") bad++ }
        END { exit !(rows >= 3 && big < 1e-8 && l == 2 && !bad) }' "$d/level.csv"; then
    echo "FAIL: hb --continue-in level against the linear closed form: $(head -n 3 "$d/level.csv") $(cat "$d/err")"; fails=$((fails + 1))
fi
total=$((total + 1))
"$sim" $lv --level-start 0.5 --level-end 2 >"$d/level.json" 2>"$d/err"
if ! grep -q '"continue_in": "level", "omega": 1.2, "level_start": 0.5, "level_end": 2,' "$d/level.json" ||
        ! grep -q '"level_reached": 2, "peaks": "sampled"' "$d/level.json" || ! grep -q '"peak_level": 2}' "$d/level.json"; then
    echo "FAIL: hb --continue-in level summary: $(cat "$d/level.json" "$d/err")"; fails=$((fails + 1))
fi
total=$((total + 1))
if "$sim" $lv --level-start 0.5 --level-end 2 --max-seconds 0 >"$d/stopped.csv" 2>"$d/err" || [ $? -ne 1 ] ||
        [ -s "$d/stopped.csv" ] || ! grep -q "^fricreg-sim: hb: --max-seconds 0 passed: stopped (the continuation from level = 0.5" "$d/err"; then
    echo "FAIL: hb --continue-in level --max-seconds 0: $(cat "$d/stopped.csv" "$d/err")"; fails=$((fails + 1))
fi
expect_usage_error "^fricreg-sim: --level-start: missing" $lv --level-end 2
expect_usage_error "^fricreg-sim: --level-end: equals --level-start" $lv --level-start 1 --level-end 1
expect_usage_error "^fricreg-sim: --omega-start: applies to --continue-in omega" $lv --level-start 0.5 --level-end 2 --omega-start 1
expect_usage_error "^fricreg-sim: --omega: applies to --continue-in level" $hb --omega 1.2
expect_usage_error "^fricreg-sim: --level-start: must be >= 0" $lv --level-start -1 --level-end 2
# Beyond the dense driver's 4096 dofs, the files passed sparse: 5000 copies of that oscillator,
# uncoupled, the element on dof 1 only, every dof forced alike; dof 1 peaks as above, within
# the branch's resolution (1 %): beyond 256 dofs the summary's peaks are the largest points'.
awk 'BEGIN { print "%%MatrixMarket matrix coordinate real symmetric"; print 5000, 5000, 5000
    for (i = 1; i <= 5000; i++) print i, i, 2 }' >"$d/Mbig.mtx"
awk 'BEGIN { print "%%MatrixMarket matrix coordinate real symmetric"; print 5000, 5000, 5000
    for (i = 1; i <= 5000; i++) print i, i, 3 }' >"$d/Kbig.mtx"
awk 'BEGIN { for (i = 1; i <= 5000; i++) print "0.5 0" }' >"$d/Fbig.txt"
printf '%s\n' "%%MatrixMarket matrix coordinate real general" "1 5000 1" "1 1 1" >"$d/Jbig.mtx"
total=$((total + 1))
"$sim" hb --mass "$d/Mbig.mtx" --stiffness "$d/Kbig.mtx" --rayleigh 0,0.02 --excitation "$d/Fbig.txt" --jenkins "$d/Jbig.mtx" --jenkins-params "$d/P.txt" --harmonics 3 --omega-start 0.5 --omega-end 3 >"$d/big.json" 2>"$d/err"
if ! grep -q '"ndof": 5000, "elements": 1' "$d/big.json" || ! grep -q '"peaks": "sampled"' "$d/big.json" ||
        ! grep -o '"dof": 1, "peak_rms": [^,]*, "peak_omega": [^}]*' "$d/big.json" |
        sed 's/.*"peak_rms": \([^,]*\), "peak_omega": \(.*\)/\1 \2/' |
        awk '{ exit !($1 > 0.99 * 3.9284 && $1 < 1.01 * 3.9284 && $2 > 1.485 && $2 < 1.515) }'; then
    echo "FAIL: hb on 5000 dofs (sparse): $(head -c 300 "$d/big.json") $(cat "$d/err")"; fails=$((fails + 1))
fi
expect_output '^usage: fricreg-sim hb --mass M\.mtx --stiffness K\.mtx' hb --help
expect_output '^  hb          ' --help
expect_usage_error "^fricreg-sim: --omega-end: missing" hb --mass $d/M.mtx --stiffness $d/K.mtx --excitation $d/F.txt --jenkins $d/J.mtx --jenkins-params $d/P.txt --omega-start 1
expect_usage_error "^fricreg-sim: --jenkins-params: missing" hb --mass $d/M.mtx --stiffness $d/K.mtx --excitation $d/F.txt --jenkins $d/J.mtx --omega-start 1 --omega-end 2
expect_usage_error "^fricreg-sim: --jenkins-2d: harmonic balance has 2-D elements with a normal law only" hb --mass $d/M.mtx --stiffness $d/K.mtx --excitation $d/F.txt --jenkins-2d $d/J.mtx --jenkins-params $d/P.txt --omega-start 1 --omega-end 2
expect_usage_error "^fricreg-sim: --jenkins-params $d/P1.txt: line 1: " hb --mass $d/M.mtx --stiffness $d/K.mtx --excitation $d/F.txt --jenkins $d/J.mtx --jenkins-params $d/P1.txt --omega-start 1 --omega-end 2
expect_usage_error "^fricreg-sim: --harmonics: " ${hb%% --harmonics *} --omega-start 0.5 --omega-end 3 --harmonics 41
expect_usage_error "^fricreg-sim: --newton-tol: .*tol" $hb --newton-tol 2
expect_usage_error "^fricreg-sim: --newton-max: " $hb --newton-max 0
# A looser Newton tolerance reaches the same peak: the rule is passed on (1e-6 of q's scale)
total=$((total + 1))
"$sim" $hb --newton-tol 1e-6 --newton-max 20 >"$d/loose.json" 2>"$d/err"
if ! sed 's/.*"peak_rms": \([^,]*\), "peak_omega": \([^}]*\)}.*/\1 \2/' "$d/loose.json" |
        awk '{ exit !($1 > 0.99 * 3.9284 && $1 < 1.01 * 3.9284 && $2 > 1.485 && $2 < 1.515) }'; then
    echo "FAIL: hb --newton-tol 1e-6: $(cat "$d/loose.json" "$d/err")"; fails=$((fails + 1))
fi
expect_usage_error "^fricreg-sim: --rayleigh: give --damping or --rayleigh" hb --mass $d/M.mtx --stiffness $d/K.mtx --damping $d/K.mtx --rayleigh 0,0.02 --excitation $d/F.txt --jenkins $d/J.mtx --jenkins-params $d/P.txt --omega-start 1 --omega-end 2
expect_usage_error "^fricreg-sim: --excitation $d/J.mtx" hb --mass $d/M.mtx --stiffness $d/K.mtx --excitation $d/J.mtx --jenkins $d/J.mtx --jenkins-params $d/P.txt --omega-start 1 --omega-end 2
# Iwan elements and lift-off in hb, against the element slipping (kt 1.5, mu N 0.3): two
# sliders of 0.75 and 0.15 give the same branch to rounding (every point within 1e-12); a lift-off element of mu 0.1,
# n0 3, kn 0 on the same row is the Jenkins element of mu N = 0.3 (fricreg_hb.h) but its
# preload pushes the mass to x0 = -n0/k = -1 (the static term), so its RMS is
# sqrt(rms_jenkins^2 + 1): at the first point (Omega = W0, solved from q = 0) within 1e-12,
# slipping near the peak (W0 = 1.24) and beyond it (1.5).
hbs="hb --mass $d/M.mtx --stiffness $d/K.mtx --rayleigh 0,0.02 --excitation $d/F.txt --jenkins $d/J.mtx --harmonics 3"
echo "1.5 0.3" >"$d/P_slip.txt"
echo "0.75 0.15 0.75 0.15" >"$d/I_slip.txt"
echo "1.5 0.1 3 0" >"$d/Q_kn0.txt"
expect_same 1e-12 $hbs --omega-start 0.5 --omega-end 3 --jenkins-params $d/P_slip.txt --output frf -- $hbs --omega-start 0.5 --omega-end 3 --iwan-params $d/I_slip.txt --output frf
# the located peak's Omega is conditioned as the square root of the RMS's rounding: 1e-9
expect_same 1e-9 $hbs --omega-start 0.5 --omega-end 3 --jenkins-params $d/P_slip.txt -- $hbs --omega-start 0.5 --omega-end 3 --iwan-params $d/I_slip.txt
expect_output '"element_kind": "iwan", "sliders_per_element": 2' $hbs --omega-start 0.5 --omega-end 3 --iwan-params $d/I_slip.txt
for w0 in 1.24 1.5; do
    total=$((total + 1))
    "$sim" $hbs --omega-start $w0 --omega-end 3 --jenkins-params $d/P_slip.txt --output frf >"$d/j.csv" 2>"$d/err"
    "$sim" $hbs --omega-start $w0 --omega-end 3 --normal $d/J.mtx --normal-params $d/Q_kn0.txt --output frf >"$d/n.csv" 2>>"$d/err"
    if ! paste -d, "$d/j.csv" "$d/n.csv" | awk -F, -v w0=$w0 'NR == 2 { e = (sqrt($7 * $7 - 1) - $2) / $2
            exit !($1 == w0 && $6 == w0 && $2 > 0.3 && e < 1e-12 && e > -1e-12) } END { if (NR < 2) exit 1 }'; then
        echo "FAIL: hb lift-off kn = 0 against Jenkins at $w0: $(sed -n 2p "$d/j.csv") $(sed -n 2p "$d/n.csv") $(cat "$d/err")"
        fails=$((fails + 1))
    fi
done
expect_output '"element_kind": "lift-off"' $hbs --omega-start 0.5 --omega-end 3 --normal $d/J.mtx --normal-params $d/Q_kn0.txt
# Iwan elements with lift-off: two halves of that element (kt/2, mu/2 each) are it
echo "3 0 0.75 0.05 0.75 0.05" >"$d/QI_kn0.txt"
expect_same 1e-12 $hbs --omega-start 0.5 --omega-end 3 --normal $d/J.mtx --normal-params $d/Q_kn0.txt --output frf -- $hbs --omega-start 0.5 --omega-end 3 --normal $d/J.mtx --iwan-normal-params $d/QI_kn0.txt --output frf
expect_output '"element_kind": "iwan-lift-off", "sliders_per_element": 2' $hbs --omega-start 0.5 --omega-end 3 --normal $d/J.mtx --iwan-normal-params $d/QI_kn0.txt
# the 3-D contact element (--jenkins-2d with --normal), stuck and closed with both tangential
# rows and the normal row on the one dof: the springs kt = 0.75 twice and kn = 2 on the
# harmonics (the slider at the centre of the orbit), the preload's static deflection
# x0 = -n0/(k + kn) = -6 (N0 = 30 keeps the contact closed at the resonance): every row's RMS
# sqrt(x0^2 + |X|^2/2), |X| = 0.5/|6.5 - 2 Omega^2 + 0.06 i Omega|, within 1e-9
printf '%s\n' "%%MatrixMarket matrix coordinate real general" "2 1 2" "1 1 1" "2 1 1" >"$d/J2.mtx"
echo "0.75 1e6 30 2" >"$d/Q3.txt"
hb3="hb --mass $d/M.mtx --stiffness $d/K.mtx --rayleigh 0,0.02 --excitation $d/F.txt --harmonics 3 --omega-start 0.5 --omega-end 3 --normal $d/J.mtx"
total=$((total + 1))
"$sim" $hb3 --jenkins-2d $d/J2.mtx --normal-params $d/Q3.txt --output frf >"$d/frf3.csv" 2>"$d/err"
if ! awk -F, 'NR > 1 { w = $1; a = 6.5 - 2 * w * w; c = 0.06 * w; x = 0.5 / sqrt(a * a + c * c)
        r = sqrt(36 + x * x / 2); e = ($2 - r) / r; if (e < 0) e = -e; if (e > big) big = e; rows++ }
        END { exit !(rows >= 20 && big < 1e-9 && w == 3) }' "$d/frf3.csv"; then
    echo "FAIL: hb 3-D contact against the linear closed form: $(head -n 3 "$d/frf3.csv") $(cat "$d/err")"; fails=$((fails + 1))
fi
expect_output '"element_kind": "contact-3d"' $hb3 --jenkins-2d $d/J2.mtx --normal-params $d/Q3.txt
# The lift-off pair of tests/forced/test_hb_continuation.c (2 unit masses, K = [140 -20; -20 180],
# C = 0.002 K, kt 40, mu 0.3, N0 2, kn 100, u = x_1, g = -x_2, p_c = (2, 1)) from 11.5 to 12.5
# rad/s with every default: the start without a guess is on the stable branch that the
# continuations from 12.5 down and from 5 up reach (the library test, to 1e-8), rms_2 =
# 0.0422997417 at 11.5 (measured), and every point stable.
printf '%s\n' "%%MatrixMarket matrix coordinate real general" "2 2 2" "1 1 1" "2 2 1" >"$d/lpM.mtx"
printf '%s\n' "%%MatrixMarket matrix coordinate real general" "2 2 4" "1 1 140" "1 2 -20" "2 1 -20" "2 2 180" >"$d/lpK.mtx"
printf '%s\n' "%%MatrixMarket matrix coordinate real general" "1 2 1" "1 1 1" >"$d/lpJ.mtx"
printf '%s\n' "%%MatrixMarket matrix coordinate real general" "1 2 1" "1 2 -1" >"$d/lpJn.mtx"
printf '%s\n' "2 0" "1 0" >"$d/lpF.txt"
echo "40 0.3 2 100" >"$d/lpQ.txt"
lp="hb --mass $d/lpM.mtx --stiffness $d/lpK.mtx --rayleigh 0,0.002 --excitation $d/lpF.txt --jenkins $d/lpJ.mtx --normal $d/lpJn.mtx --normal-params $d/lpQ.txt --omega-start 11.5 --omega-end 12.5"
expect_output '"omega_reached": 12.5, ' $lp
total=$((total + 1))
"$sim" $lp --output frf >"$d/lp.csv" 2>"$d/err"
if [ $? -ne 0 ] || ! awk -F, 'NR == 2 { ok = $1 == 11.5 && $3 > 0.04229974 && $3 < 0.04229975 }
        NR > 1 && $5 == "" { rows++; if ($4 != 1) bad++ } END { exit !(ok && rows > 10 && !bad) }' "$d/lp.csv"; then
    echo "FAIL: hb lift-off pair 11.5 to 12.5 by default: $(head -n 3 "$d/lp.csv") $(cat "$d/err")"; fails=$((fails + 1))
fi
# The gap pair (that pair turned round: u = x_2, g = -x_1, mu 0.01, N0 -10, kn 500) at 1.5
# times its excitation, p_c = (3, 1.5), from 3.55 to 4.05 rad/s with every default: the level's
# branch from the linear regime ends on a closed branch, unstable there, and 1.7 went round it
# and exited 1 ("doubles back"); the start now takes the stable solution that the sweeps from
# 2.05 up and 5.05 down reach (test_hb_level's unstable_start_takes_the_stable_branch, to 1e-8):
# exit 0, rms_2 at 3.55 within 1e-8 of the measured 0.0084168958, every point stable, the end
# reached, "isola": false. At twice the excitation, p_c = (4, 2), from 5 the start lies on an
# isola, stable there (test_hb_continuation's closed_branch_is_returned): exit 0 with its
# points, "isola": true, the last point short of 5.5.
printf '%s\n' "%%MatrixMarket matrix coordinate real general" "1 2 1" "1 2 1" >"$d/gpJ.mtx"
printf '%s\n' "%%MatrixMarket matrix coordinate real general" "1 2 1" "1 1 -1" >"$d/gpJn.mtx"
echo "40 0.01 -10 500" >"$d/gpQ.txt"
printf '%s\n' "3 0" "1.5 0" >"$d/gpF15.txt"
printf '%s\n' "4 0" "2 0" >"$d/gpF2.txt"
gp="hb --mass $d/lpM.mtx --stiffness $d/lpK.mtx --rayleigh 0,0.002 --jenkins $d/gpJ.mtx --normal $d/gpJn.mtx --normal-params $d/gpQ.txt"
expect_output '"omega_reached": 4.0499999999999998, .*"isola": false, ' $gp --excitation $d/gpF15.txt --omega-start 3.55 --omega-end 4.05
total=$((total + 1))
"$sim" $gp --excitation $d/gpF15.txt --omega-start 3.55 --omega-end 4.05 --output frf >"$d/gp.csv" 2>"$d/err"
if [ $? -ne 0 ] || ! awk -F, 'NR == 2 { ok = $1 == 3.55 && $3 > 0.00841689578 && $3 < 0.00841689580 }
        NR > 1 && $5 == "" { rows++; last = $1; if ($4 != 1) bad++ } END { exit !(ok && rows > 5 && !bad && last == 4.05) }' "$d/gp.csv"; then
    echo "FAIL: hb gap pair 3.55 to 4.05 by default: $(head -n 3 "$d/gp.csv") $(cat "$d/err")"; fails=$((fails + 1))
fi
expect_output '"omega_start": 5, "omega_end": 5.5, "points": [0-9]+, .*"omega_reached": 4\.9[0-9]*, .*"isola": true, ' $gp --excitation $d/gpF2.txt --omega-start 5 --omega-end 5.5
echo "1.5 0.1 3 -1" >"$d/Q_bad.txt"
expect_usage_error "^fricreg-sim: --normal-params $d/Q_bad.txt: .*kn" $hbs --omega-start 1 --omega-end 2 --normal $d/J.mtx --normal-params $d/Q_bad.txt
expect_usage_error "^fricreg-sim: --iwan-params $d/P1.txt: line 1: 1 numbers: give pairs" $hbs --omega-start 1 --omega-end 2 --iwan-params $d/P1.txt
expect_usage_error "^fricreg-sim: --jenkins: missing (a file is required)" hb --mass $d/M.mtx --stiffness $d/K.mtx --excitation $d/F.txt --omega-start 1 --omega-end 2
# Element sets of several kinds in one run (--elements TYPE:J.mtx:P.txt, repeatable, structure's
# syntax; each set added by fricreg_hb_add_elements in order). (a) One jenkins set is --jenkins
# with --jenkins-params, the slipping element above: the same summary (its element_sets and CPU
# time dropped) and the same CSV, to the last digit (one kind is the per-kind setter, bit for
# bit).
"$sim" $hbs --omega-start 0.5 --omega-end 3 --jenkins-params $d/P_slip.txt >"$d/es_old.json" 2>"$d/err"
"$sim" ${hbs%% --jenkins *} --elements jenkins:$d/J.mtx:$d/P_slip.txt --harmonics 3 --omega-start 0.5 --omega-end 3 >"$d/es_new.json" 2>>"$d/err"
"$sim" $hbs --omega-start 0.5 --omega-end 3 --jenkins-params $d/P_slip.txt --output frf >"$d/es_old.csv" 2>>"$d/err"
"$sim" ${hbs%% --jenkins *} --elements jenkins:$d/J.mtx:$d/P_slip.txt --harmonics 3 --omega-start 0.5 --omega-end 3 --output frf >"$d/es_new.csv" 2>>"$d/err"
total=$((total + 1))
sed -e 's/"cpu_seconds": [0-9.e+-]*//' "$d/es_old.json" >"$d/es_old.txt"
sed -e 's/"cpu_seconds": [0-9.e+-]*//; s/, "element_sets": \[[^]]*\]//' "$d/es_new.json" >"$d/es_new.txt"
if ! grep -q '"elements": 1, .*"element_kind": "jenkins", "element_sets": \[{"type": "jenkins", "nelements": 1, "sliders_per_element": 1}\], "stability_method": "monodromy"' "$d/es_new.json" ||
   ! grep -q '"peak_rms": 1\.46' "$d/es_old.txt" || ! cmp -s "$d/es_old.txt" "$d/es_new.txt" ||
   [ "$(wc -l <"$d/es_old.csv")" -lt 20 ] || ! cmp -s "$d/es_old.csv" "$d/es_new.csv"; then
    echo "FAIL: hb --elements jenkins is not --jenkins with --jenkins-params: $(head -c 500 "$d/es_new.json") | $(head -c 300 "$d/es_old.json") $(cat "$d/err")"; fails=$((fails + 1))
fi
# (b) Two kinds: two decoupled copies of that oscillator (M, K block-diagonal, Rayleigh C, both
# dofs forced alike), the slipping Jenkins element on dof 1 and an Iwan element of 3 sliders on
# dof 2 (its line in the kernel's layout k_1 k_2 k_3 phi_1 phi_2 phi_3, where --iwan-params takes
# pairs). Each dof is its oscillator run alone by the old options: the located peak's RMS and
# the first point's RMS (W0 = 1.24, slipping; solved from q = 0) to 1e-10 relative, the same
# verdict of stability; the peak's Omega, conditioned as the square root of the RMS's rounding,
# to 1e-9 (measured: 3e-15 and 4e-10). The summary counts 2 elements of a mixed kind, Hill's
# stability (the monodromy takes one kind).
decoupled hb 2 3 2 3
printf '0.5 0\n0.5 0\n' >"$d/F2.txt"
echo "0.75 0.5 0.25 0.1 0.1 0.1" >"$d/E_iwan3.txt"
echo "0.75 0.1 0.5 0.1 0.25 0.1" >"$d/I_iwan3.txt"
hb2="hb --mass $d/hbM22.mtx --stiffness $d/hbK22.mtx --rayleigh 0,0.02 --excitation $d/F2.txt --harmonics 3 --omega-end 3"
mix="--elements jenkins:$d/hbJ1of2.mtx:$d/P_slip.txt --elements iwan:$d/hbJ2of2.mtx:$d/E_iwan3.txt"
"$sim" $hb2 --omega-start 0.5 $mix >"$d/mix.json" 2>"$d/err"
"$sim" $hbs --omega-start 0.5 --omega-end 3 --jenkins-params $d/P_slip.txt >"$d/alone1.json" 2>>"$d/err"
"$sim" $hbs --omega-start 0.5 --omega-end 3 --iwan-params $d/I_iwan3.txt >"$d/alone2.json" 2>>"$d/err"
"$sim" $hb2 --omega-start 1.24 $mix --output frf >"$d/mix.csv" 2>>"$d/err"
"$sim" $hbs --omega-start 1.24 --omega-end 3 --jenkins-params $d/P_slip.txt --output frf >"$d/alone1.csv" 2>>"$d/err"
"$sim" $hbs --omega-start 1.24 --omega-end 3 --iwan-params $d/I_iwan3.txt --output frf >"$d/alone2.csv" 2>>"$d/err"
total=$((total + 1))
# peaks FILE: each dof's "peak_rms peak_omega" of a summary, one line each
peaks() { sed -e 's/.*"dofs": \[//; s/\].*//; s/}, {/\n/g' "$1" | sed -n 's/.*"peak_rms": \([^,]*\), "peak_omega": \([^}]*\).*/\1 \2/p'; }
mixed=$(peaks "$d/mix.json" | tr '\n' ' ')
alone=$(peaks "$d/alone1.json"; peaks "$d/alone2.json")
rows=$(sed -n 2p "$d/mix.csv"; sed -n 2p "$d/alone1.csv"; sed -n 2p "$d/alone2.csv")
if ! grep -q '"ndof": 2, "elements": 2, .*"element_kind": "mixed", "element_sets": \[{"type": "jenkins", "nelements": 1, "sliders_per_element": 1}, {"type": "iwan", "nelements": 1, "sliders_per_element": 3}\], "stability_method": "hill"' "$d/mix.json" ||
   ! echo $mixed $alone | awk '{ for (k = 1; k <= 4; k++) { d = $k - $(k + 4); if (d < 0) d = -d
            if (!($k > 1 && d <= (k % 2 ? 1e-10 : 1e-9) * $k)) exit 1 } }' ||
   ! echo "$rows" | tr '\n' ',' | awk -F, '{ for (k = 2; k <= 3; k++) { a = $k; b = $(k == 2 ? 8 : 13); d = a - b; if (d < 0) d = -d
            if (!(a > 0.3 && d <= 1e-10 * a)) exit 1 }
        exit !($1 == 1.24 && $7 == 1.24 && $12 == 1.24 && $4 == 1 && $9 == 1 && $14 == 1) }'; then
    echo "FAIL: hb --elements jenkins and iwan against each alone: peaks $mixed | $alone; rows $rows; $(head -c 400 "$d/mix.json") $(cat "$d/err")"; fails=$((fails + 1))
fi
# (d) Its usage errors: beside the old options; a type the kernel does not know; a type harmonic
# balance does not take (the library's reason, naming the set's file: a gap on jenkins_normal,
# whose normal law HB's exact AFT takes as n0 + kn g); the exact monodromy on a mix (the library's reason, naming --stability), as on
# the 3-D contact element.
mtx hbJ2d.mtx general "2 2 2" "1 1 1" "2 2 1"
expect_usage_error "^fricreg-sim: --elements: give --elements or the element options" $hb2 --omega-start 0.5 $mix --jenkins $d/hbJ1of2.mtx --jenkins-params $d/P_slip.txt
expect_usage_error "^fricreg-sim: --elements: unknown element type 'jenkin' (jenkins, " $hb2 --omega-start 0.5 --elements jenkin:$d/hbJ1of2.mtx:$d/P_slip.txt
printf '1 0.3 2 0 0.1\n' > "$d/P_gap.txt"
expect_usage_error "^fricreg-sim: --elements $d/hbJ2d.mtx: add_elements: element 0 (jenkins_normal): gap = 0.1" $hb2 --omega-start 0.5 --elements jenkins_normal:$d/hbJ2d.mtx:$d/P_gap.txt
expect_usage_error "^fricreg-sim: --elements $d/E_iwan3.txt: line 1: 6 numbers: jenkins takes 2 parameters" $hb2 --omega-start 0.5 --elements jenkins:$d/hbJ1of2.mtx:$d/E_iwan3.txt
expect_usage_error "^fricreg-sim: --stability: .*monodromy needs .* all of one kind" $hb2 --omega-start 0.5 $mix --stability monodromy
expect_usage_error "^fricreg-sim: --stability: .*monodromy needs " $hb3 --jenkins-2d $d/J2.mtx --normal-params $d/Q3.txt --stability monodromy
# Harmonic balance has no fixed bound on the elements (256 until 1.8): 257 springs on dof 1 run.
{ printf '%%%%MatrixMarket matrix coordinate real general\n257 2 257\n'; seq 1 257 | sed 's/$/ 1 1/'; } > "$d/J257.mtx"
seq 1 257 | sed 's/.*/0.5/' > "$d/P257.txt"
expect_output '"elements": 257, "harmonics": 1, .*"omega_reached": 0.59999' hb --mass $d/hbM22.mtx --stiffness $d/hbK22.mtx --rayleigh 0,0.02 --excitation $d/F2.txt --harmonics 1 --omega-start 0.5 --omega-end 0.6 --elements spring:$d/J257.mtx:$d/P257.txt

# ---- nma: the backbone of a nonlinear mode (fricreg_hb_nma) from the files of hb.
# One unit mass on a unit spring with a Jenkins element kt = 2, mu N = 3 at H = 1: stuck for
# a <= 1.5 (omega^2 = 3, zeta = 0); beyond, with cos(beta) = 1 - 3/a, the describing function's
# omega^2 = 1 + (2/pi)(beta - sin(2 beta)/2), zeta = 12 (a - 1.5) / (2 pi a^2 omega^2)
# (tests/nma/test_hb_nma.c derives it): every row of --output backbone within 1e-9.
d=$tmp/nma
mkdir -p "$d"
printf '%s\n' "%%MatrixMarket matrix coordinate real symmetric" "1 1 1" "1 1 1" >"$d/M.mtx"
printf '%s\n' "%%MatrixMarket matrix coordinate real general" "1 1 1" "1 1 1" >"$d/J.mtx"
echo "2 3" >"$d/P.txt"
nma="nma --mass $d/M.mtx --stiffness $d/M.mtx --jenkins $d/J.mtx --jenkins-params $d/P.txt --harmonics 1 --amplitude-start 0.5 --amplitude-end 500"
total=$((total + 1))
# closed_form_rows FILE ROWS: FILE is the backbone's CSV with ROWS rows, each on the closed form
# (at H = 1 the one harmonic carries all the kinetic energy: e_h1 = 1).
closed_form_rows() {
    [ "$(head -n 1 "$1")" = "amplitude,omega,zeta,e_h1" ] && awk -F, -v want="$2" 'NR > 1 { a = $1; w2 = 3; z = 0
        if ($4 != 1) bad++
        if (a > 1.5) { c = 1 - 3 / a; b = atan2(sqrt(1 - c * c), c); pi = atan2(0, -1)
            w2 = 1 + 2 / pi * (b - sin(2 * b) / 2); z = 12 * (a - 1.5) / (2 * pi * a * a * w2) }
        e = ($2 * $2 - w2) / w2; if (e < 0) e = -e; if (e > big) big = e
        e = $3 - z; if (e < 0) e = -e; if (e > 1e-9 * (z > 0 ? z : 1)) bad++; rows++ }
        END { exit !(rows == want && big < 1e-9 && !bad) }' "$1"
}
"$sim" $nma --points 12 --output backbone >"$d/backbone.csv" 2>"$d/err"
if ! closed_form_rows "$d/backbone.csv" 12; then
    echo "FAIL: nma backbone against the closed form: $(head -n 4 "$d/backbone.csv") $(cat "$d/err")"; fails=$((fails + 1))
fi
total=$((total + 1))
# A march that fails writes what it reached: no point here, the summary saying so.
if "$sim" $nma --max-seconds 0 >"$d/stopped.json" 2>"$d/err" || [ $? -ne 1 ] ||
        ! grep -q '"points": 0, "folds": \[\], "crossings": \[\], "complete": false, "error": "nma_continue: stopped' "$d/stopped.json" ||
        ! grep -q "^fricreg-sim: nma: --max-seconds 0 passed: stopped (the backbone had reached 0 of its 20 points)$" "$d/err"; then
    echo "FAIL: nma --max-seconds 0: $(cat "$d/stopped.json" "$d/err")"; fails=$((fails + 1))
fi
# 1.7's march (--continuation natural): one Newton iteration a point reaches 2 of 12 points (the
# march past the first slip at a = 1.5 needs more): those two rows, each on the closed form,
# then the failure on stderr and exit status 1. (With two iterations the whole backbone passes
# since 1.10: the march no longer takes a step a rounding short of a grid point.)
total=$((total + 1))
if "$sim" $nma --continuation natural --points 12 --newton-max 1 --output backbone >"$d/part.csv" 2>"$d/err" || [ $? -ne 1 ] ||
        ! closed_form_rows "$d/part.csv" 2 ||
        ! grep -q "^fricreg-sim: nma: the backbone failed after 2 of its 12 points: nma: Newton did not converge in 1 iterations" "$d/err"; then
    echo "FAIL: nma --newton-max 1, the points reached: $(cat "$d/part.csv" "$d/err")"; fails=$((fails + 1))
fi
total=$((total + 1))
if "$sim" $nma --continuation natural --points 12 --newton-max 1 >"$d/part.json" 2>"$d/err" || [ $? -ne 1 ] ||
        ! grep -q '"points": 2, "first": {"amplitude": 0.5,.*"complete": false, "error": "nma: Newton did not converge' "$d/part.json"; then
    echo "FAIL: nma --newton-max 1, the summary: $(cat "$d/part.json" "$d/err")"; fails=$((fails + 1))
fi
total=$((total + 1))
"$sim" $nma >"$d/summary.json" 2>"$d/err"
if ! grep -q '"command": "nma".*"first": {"amplitude": 0.5, "omega": 1.73205080756887[0-9]*, "zeta": 0}.*"complete": true, "cpu' "$d/summary.json"; then
    echo "FAIL: nma summary: $(cat "$d/summary.json" "$d/err")"; fails=$((fails + 1))
fi
total=$((total + 1))
"$sim" $nma --continuation natural --points 12 --output backbone >"$d/natural.csv" 2>"$d/err"
if ! closed_form_rows "$d/natural.csv" 12; then
    echo "FAIL: nma --continuation natural against the closed form: $(cat "$d/natural.csv" "$d/err")"; fails=$((fails + 1))
fi
# A backbone that folds (tests/nma/test_hb_nma_fold.c's two masses, a Jenkins element on dof 2: an
# internal resonance through the third harmonic at a = 4.43): the summary lists its two folds,
# and the written points go back in the amplitude between them; 1.7's march stops there. No
# crossing: 3 omega stays above the second stuck mode's 3.2337 (tests/nma/test_hb_nma_energy.c); the
# third harmonic's share of the kinetic energy peaks near the folds (5.2e-4 at a = 4.47).
printf '%s\n' "%%MatrixMarket matrix coordinate real symmetric" "2 2 2" "1 1 1" "2 2 1" >"$d/M2.mtx"
printf '%s\n' "%%MatrixMarket matrix coordinate real symmetric" "2 2 3" "1 1 1.25" "2 1 -0.25" "2 2 0.45" >"$d/K2.mtx"
printf '%s\n' "%%MatrixMarket matrix coordinate real general" "1 2 1" "1 2 1" >"$d/J2.mtx"
echo "10 1" >"$d/P2.txt"
fold="nma --mass $d/M2.mtx --stiffness $d/K2.mtx --jenkins $d/J2.mtx --jenkins-params $d/P2.txt --harmonics 3 --amplitude-start 2 --amplitude-end 10"
total=$((total + 1))
if ! "$sim" $fold >"$d/fold.json" 2>"$d/err" ||
        ! grep -q '"folds": \[{"amplitude": 4\.43[0-9]*, "omega": 1\.1143[0-9]*, "zeta": 0\.003[0-9]*}, {"amplitude": 4\.41[0-9]*, "omega": 1\.1148[0-9]*, "zeta": 0\.008[0-9]*}\], "crossings": \[\], "complete": true' "$d/fold.json"; then
    echo "FAIL: nma through a fold, the summary: $(cat "$d/fold.json" "$d/err")"; fails=$((fails + 1))
fi
total=$((total + 1))
if ! "$sim" $fold --points 200 --output backbone >"$d/fold.csv" 2>"$d/err" ||
        [ "$(head -n 1 "$d/fold.csv")" != "amplitude,omega,zeta,e_h1,e_h2,e_h3" ] ||
        ! awk -F, 'NR > 2 && $1 < prev { back++ } NR > 1 { prev = $1; rows++; s = $4 + $5 + $6 - 1; if (s < 0) s = -s; if (s > 1e-12) bad++
            if ($6 > top) { top = $6; at = $1 } } END { exit !(rows == 200 && back > 0 && !bad && top > 4e-4 && at > 4.3 && at < 4.6) }' "$d/fold.csv" ||
        "$sim" $fold --continuation natural >/dev/null 2>&1; then
    echo "FAIL: nma through a fold, the backbone: $(head -n 3 "$d/fold.csv") $(cat "$d/err")"; fails=$((fails + 1))
fi
# With kt = 11 the second stuck mode's frequency, sqrt(6.35 + sqrt(5.1^2 + 0.25^2)) = 3.38469,
# lies in 3 omega's range: the summary names the crossing, mode 2 (from 1, as --mode), at
# a = 5.04, omega = 3.384690/3 = 1.128230 (tests/nma/test_hb_nma_energy.c).
echo "11 1" >"$d/P3.txt"
total=$((total + 1))
if ! "$sim" ${fold%% --jenkins-params *} --jenkins-params $d/P3.txt --harmonics 3 --amplitude-start 2 --amplitude-end 10 --points 60 >"$d/cross.json" 2>"$d/err" ||
        ! grep -q '"crossings": \[{"harmonic": 3, "mode": 2, "amplitude": 5\.0[0-9]*, "omega": 1\.128229[0-9]*}\]' "$d/cross.json"; then
    echo "FAIL: nma, a crossing 3 omega = omega_2: $(cat "$d/cross.json" "$d/err")"; fails=$((fails + 1))
fi
expect_output '^usage: fricreg-sim nma --mass M\.mtx --stiffness K\.mtx' nma --help
expect_output '^  nma         ' --help
expect_usage_error "^fricreg-sim: --amplitude-end: missing" nma --mass $d/M.mtx --stiffness $d/M.mtx --jenkins $d/J.mtx --jenkins-params $d/P.txt --amplitude-start 1
expect_usage_error "^fricreg-sim: --amplitude-end: must be above" ${nma% --amplitude-end 500} --amplitude-end 0.5
expect_usage_error "^fricreg-sim: --mode: beyond" $nma --mode 2
expect_usage_error "^fricreg-sim: --linear-damping: " $nma --linear-damping none
# (c) nma with element sets of two kinds (--elements, as hb): two decoupled blocks, the Jenkins
# oscillator above (m 1, k 1, kt 2, mu N 3) on dof 1 and an Iwan element of 3 sliders (0.75,
# 0.5, 0.25; phi 1 each) on dof 2 (m 1, k 4): mode 1 is the first block's, mode 2 the second's
# (stuck: sqrt(3) < sqrt(5.5)), and each backbone is that block's run alone by the old options,
# every number of its 12 rows within 1e-12 relative (measured: equal to the last digit; the
# other block stays at rest). The summary counts 2 elements of a mixed kind.
decoupled nm 1 1 1 4
mtx nmK4.mtx symmetric "1 1 1" "1 1 4"
echo "0.75 0.5 0.25 1 1 1" >"$d/E_iwan3.txt"
echo "0.75 1 0.5 1 0.25 1" >"$d/I_iwan3.txt"
nm2="nma --mass $d/nmM22.mtx --stiffness $d/nmK22.mtx --elements jenkins:$d/nmJ1of2.mtx:$d/P.txt --elements iwan:$d/nmJ2of2.mtx:$d/E_iwan3.txt --harmonics 3 --amplitude-start 0.5 --amplitude-end 50 --points 12"
nmo="nma --mass $d/M.mtx --jenkins $d/J.mtx --harmonics 3 --amplitude-start 0.5 --amplitude-end 50 --points 12 --output backbone"
"$sim" $nm2 --mode 1 --output backbone >"$d/mix1.csv" 2>"$d/err"
"$sim" $nm2 --mode 2 --output backbone >"$d/mix2.csv" 2>>"$d/err"
"$sim" $nmo --stiffness $d/M.mtx --jenkins-params $d/P.txt >"$d/alone1.csv" 2>>"$d/err"
"$sim" $nmo --stiffness $d/nmK4.mtx --iwan-params $d/I_iwan3.txt >"$d/alone2.csv" 2>>"$d/err"
for k in 1 2; do
    total=$((total + 1))
    if [ "$(wc -l <"$d/alone$k.csv")" -ne 13 ] || ! paste -d, "$d/mix$k.csv" "$d/alone$k.csv" | awk -F, 'NR == 1 { next }
            { for (i = 1; i <= 6; i++) { d = $i - $(i + 6); s = $i; if (d < 0) d = -d; if (s < 0) s = -s
                if (d > 1e-12 * s) bad++ }; if ($3 > 0) slip++ }
            END { exit !(NR == 13 && !bad && slip > 3) }'; then
        echo "FAIL: nma --elements jenkins and iwan, mode $k against its block alone: $(head -n 5 "$d/mix$k.csv" "$d/alone$k.csv") $(cat "$d/err")"; fails=$((fails + 1))
    fi
done
expect_output '"ndof": 2, "elements": 2, "element_kind": "mixed", "element_sets": \[\{"type": "jenkins", "nelements": 1, "sliders_per_element": 1\}, \{"type": "iwan", "nelements": 1, "sliders_per_element": 3\}\], "harmonics": 3, .*"complete": true' $nm2
expect_usage_error "^fricreg-sim: --elements: give --elements or the element options" $nm2 --jenkins-params $d/P.txt
expect_usage_error "^fricreg-sim: --elements $d/nmJ1of2.mtx: 1 rows: jenkins_normal takes 2 per element" nma --mass $d/nmM22.mtx --stiffness $d/nmK22.mtx --elements jenkins_normal:$d/nmJ1of2.mtx:$d/P.txt --amplitude-start 0.5 --amplitude-end 50
mtx nmJ2d.mtx general "2 2 2" "1 1 1" "2 2 1"
printf '1 0.3 2 0 0.1\n' > "$d/P_gap.txt"
expect_usage_error "^fricreg-sim: --elements $d/nmJ2d.mtx: add_elements: element 0 (jenkins_normal): gap = 0.1" nma --mass $d/nmM22.mtx --stiffness $d/nmK22.mtx --elements jenkins_normal:$d/nmJ2d.mtx:$d/P_gap.txt --amplitude-start 0.5 --amplitude-end 50

# ---- hold, belt, disk: the reference problems beyond the paper (src/problems/, the code the
# benchmarks run; docs/laws2d.md). Values against the bench and tests/law/test_hold.c.
# num FIELD FILE: the number after "FIELD": in a JSON summary.
num() { sed -n -e "s/.*\"$1\": \(-\{0,1\}[0-9.e+-]*\).*/\1/p" "$2"; }
# within NAME FILE EXPR: awk's EXPR over the summary's fields (given as variables) is true.
within() {
    total=$((total + 1))
    name=$1 file=$2 expr=$3
    vars=$(sed -e 's/[{}]//g' -e 's/\[[^]]*\]//g' "$file" | tr ',' '\n' |
           sed -n -e 's/^ *"\([a-z_]*\)": \(-\{0,1\}[0-9][0-9.e+-]*\)$/-v \1=\2/p' | tr '\n' ' ')
    # shellcheck disable=SC2086
    if ! awk $vars "BEGIN { exit !($expr) }"; then
        echo "FAIL: $name: $expr with $(cat "$file")"; fails=$((fails + 1))
    fi
}
# hold: from rest inside the friction disk (tan theta = 0.8 mu), 10^7 steps: creep exactly 0 m/s
# and no displacement at all (the law returns f_eq itself at v = 0). (The estimate off: its
# reruns at dt/2 and dt/4 would take 6x the run; it is tested on the shorter run below.)
if [ "$long" = 1 ]; then
    expect_output '"steps": 10000000, .*"creep": 0, "displacement": 0, "slides": false' hold --error-estimate off
fi
# ... in another direction, just inside the bound (theta 1.8e-6 deg below atan(mu): |F| =
# (1 - 7.5e-8) mu N): still exactly 0.
expect_output '"creep": 0, "displacement": 0, "slides": false' hold --phi-deg 217.3 --theta-deg 28.3024623 --steps 100000
# ... and so are its reruns at eps/2 and eps/4: error estimates 0, the Coulomb solution's error.
# Their kind: bound (three equal values show no order).
expect_output '"creep_error_estimate": 0, "creep_error_kind": "bound", "displacement_error_estimate": 0, "displacement_error_kind": "bound", "error_estimate_kinds": \{"asymptotic": 0, "bound": 2, "assumed": 0\}, "cpu_seconds": [0-9.]+, "warnings": \[\]' hold --phi-deg 217.3 --theta-deg 28.3024623 --steps 100000
expect_usage_error "--answer-rtol" hold --answer-rtol -1
# ... and outside it (29 deg) the block slides at g (sin theta - mu cos theta) = 0.135641967
# m/s^2 from the first step (in the band too the law gives -mu N u when f_eq is beyond the
# disk along -u), which RK4 integrates exactly: 0.0271283934013776 m/s after 0.2 s.
"$sim" hold --theta-deg 29 --steps 2000 >"$tmp/hold.json" 2>"$tmp/err"
within "hold slides at the closed-form rate" "$tmp/hold.json" \
    'creep > 0.02712839340137 && creep < 0.02712839340138 && creep_error_estimate < 1e-12'
expect_output '"slides": true' hold --theta-deg 29 --steps 2000
# Tilting at 0.02 rad/s (1.1459156 deg/s) from 0.9 atan(mu): the block leaves rest in the step
# whose tilts bracket atan(mu) = 28.3024640990 deg; the bracket's midpoint is within kappa dt of
# it, in any direction.
"$sim" hold --tilt-rate 1.1459156 >"$tmp/hold.json" 2>"$tmp/err"
within "hold break-away within kappa dt" "$tmp/hold.json" \
    'error_deg <= bound_deg && -error_deg <= bound_deg && bound_deg < 1.2e-4 && exact_deg > 28.30246409 && exact_deg < 28.30246410'
# ... and its error estimate from the reruns at eps/2, dt/2 and eps/4, dt/4 bounds the error
# against the exact atan(mu) (5.05e-5 deg; the estimate 5.9e-4: a break-away located at a
# step's end shows no order in eps, the safe bound without a warning).
within "hold break-away's estimate bounds its error" "$tmp/hold.json" \
    'breakaway_deg_error_estimate >= error_deg && breakaway_deg_error_estimate >= -error_deg && breakaway_deg_error_estimate < 1e-3'
if ! grep -q '"warnings": \[\]}$' "$tmp/hold.json" || [ -s "$tmp/err" ]; then
    echo "FAIL: hold break-away warned: $(cat "$tmp/err" "$tmp/hold.json")"; fails=$((fails + 1))
fi
"$sim" hold --tilt-rate 0.3 --phi-deg 123 --dt 1e-3 >"$tmp/hold.json" 2>"$tmp/err"
within "hold break-away within kappa dt (dt 1e-3)" "$tmp/hold.json" \
    'error_deg <= bound_deg && -error_deg <= bound_deg && bound_deg > 2.9e-4 && bound_deg < 3.1e-4 && breakaway_deg_error_estimate >= error_deg && breakaway_deg_error_estimate >= -error_deg'
expect_output '^t,theta,x1,x2,v1,v2$' hold --tilt-rate 5 --output trajectory
expect_usage_error "--mu" hold --mu -1
expect_usage_error "--theta-deg" hold --theta-deg 95
expect_usage_error "--steps" hold --steps 3
expect_usage_error "--steps" hold --steps 1e11
expect_usage_error "--tilt-rate" hold --tilt-rate nan
expect_usage_error "--tilt-rate" hold --tilt-rate 1e-300
expect_usage_error "--dt" hold --dt 0.01 --eps 0.002
expect_usage_error "--fs" hold --fs 1
# belt: the event-driven reference's limit cycle (period 9.415410941, amplitude 0.5919801876 in
# bench/stribeck_belt.c), and the regularized law at dt 0.0025, eps 0.005 within 1e-3 of both.
if [ "$long" = 1 ]; then
    "$sim" belt --dt 0.0025 --eps 0.005 >"$tmp/belt.json" 2>"$tmp/err"
    expect_in "$tmp/belt.json" '"reference": \{"method": "event-driven", "dt": 1(\.0+1)?e-05, "period": 9\.41541094[0-9]*, "amplitude": 0\.59198018[0-9]*,'
    within "belt within 1e-3 of the reference" "$tmp/belt.json" \
        'period_error < 1e-3 && amplitude_error < 1e-3 && period > 9.41 && period < 9.42'
    # ... the error estimates from reruns at eps/2, dt/2 and eps/4, dt/4 (absolute; period and
    # amplitude here are the reference's, the last given) bound the errors against the event-driven
    # reference within 10x (measured: 2.0x both).
    within "belt's estimates bound its errors" "$tmp/belt.json" \
        'period_error_estimate >= period_error * period && period_error_estimate <= 10 * period_error * period && amplitude_error_estimate >= amplitude_error * amplitude && amplitude_error_estimate <= 10 * amplitude_error * amplitude'
    # ... second order in dt = eps/2: halving dt divides both errors by more than 3.
    "$sim" belt --dt 0.00125 >"$tmp/belt2.json" 2>"$tmp/err"
    total=$((total + 1))
    if ! awk -v a="$(num period_error "$tmp/belt.json")" -v b="$(num period_error "$tmp/belt2.json")" \
            -v c="$(num amplitude_error "$tmp/belt.json")" -v d="$(num amplitude_error "$tmp/belt2.json")" \
            'BEGIN { exit !(b > 0 && d > 0 && a / b > 3 && c / d > 3) }'; then
        echo "FAIL: belt errors not second order: $(cat "$tmp/belt.json" "$tmp/belt2.json")"; fails=$((fails + 1))
    fi
fi
# Stribeck with delta < 1 (docs/laws2d.md, "Warnings"): the band's error (fs - fk)/fs
# (eps/vs)^delta = 0.3 x 0.5 = 0.15 warns, once on stderr and in the JSON; at delta = 1 the
# same run (0.075) and the defaults raise none.
"$sim" belt --fs 1 --fk 0.7 --vs 0.02 --delta 0.5 --v-belt 0.1 --dt 0.0025 --eps 0.005 --cycles 3 >"$tmp/sb.json" 2>"$tmp/err"
total=$((total + 1))
if [ "$(grep -c '^fricreg-sim: warning: Stribeck delta = 0.5 < 1' "$tmp/err")" != 1 ] ||
        ! grep -q '"warnings": \[{"code": "stribeck_eps", "message": "Stribeck delta = 0.5 < 1: .* = 0.15 and' "$tmp/sb.json"; then
    echo "FAIL: belt delta 0.5 warning: $(cat "$tmp/err" "$tmp/sb.json")"; fails=$((fails + 1))
fi
"$sim" belt --fs 1 --fk 0.7 --vs 0.02 --delta 1 --v-belt 0.1 --dt 0.0025 --eps 0.005 --cycles 3 >"$tmp/sb1.json" 2>"$tmp/err"
total=$((total + 1))
if [ -s "$tmp/err" ] || ! grep -q '"warnings": \[\]}$' "$tmp/sb1.json" ||
   { [ "$long" = 1 ] && ! grep -q '"warnings": \[\]}$' "$tmp/belt.json"; }; then
    echo "FAIL: belt warned at delta = 1 or with its defaults: $(cat "$tmp/err" "$tmp/sb1.json")"; fails=$((fails + 1))
fi
expect_output '^t,x,v,f$' belt --output trajectory --cycles 2
expect_usage_error "--fk" belt --fk 2
expect_usage_error "--cycles" belt --cycles 1.5
expect_usage_error "--vs" belt --vs 0
expect_usage_error "--dt" belt --dt 0.05 --eps 0.01
expect_usage_error "--law" belt --law quinn
expect_usage_error "--dt" belt --dt 1e-9 --eps 0.01
expect_usage_error "--ref-dt" belt --ref-dt 1e-12
expect_usage_error "--dt" belt --v-belt 1e-300
# disk: D per forcing cycle of the 2-D oscillator with rotating forcing against the same
# problem at eps = 2e-4 (docs/laws2d.md's comparison: the default law within 1e-4 at dt 0.005).
if [ "$long" = 1 ]; then
    "$sim" disk --dt 0.005 >"$tmp/disk.json" 2>"$tmp/err"
    within "disk D against its reference" "$tmp/disk.json" \
        'relative_error < 1e-4 && dissipation_per_cycle > 10.01 && dissipation_per_cycle < 10.02'
    # ... D's error estimate from reruns at eps/2, dt/2 and eps/4, dt/4 bounds its difference to the
    # reference run at eps = 2e-4 within 10x (dissipation_per_cycle here is the reference's, the
    # last given; measured 8.4e-6 against 4.2e-6); none with --error-estimate off; one companion's
    # 3 |D - D(eps/2)| with one.
    within "disk's estimate bounds its error" "$tmp/disk.json" \
        'dissipation_per_cycle_error_estimate >= relative_error * dissipation_per_cycle && dissipation_per_cycle_error_estimate <= 10 * relative_error * dissipation_per_cycle'
fi
expect_output '"dissipation_per_cycle_error_estimate": [0-9.]+e-0[56], "dissipation_per_cycle_error_kind": "assumed", "error_estimate_kinds": \{"asymptotic": 0, "bound": 0, "assumed": 1\}, "cpu_seconds": [0-9.]+, "warnings": \[\]}$' disk --ref-eps 0 --error-estimate one
# ... its estimate, 4e-6 of D, exceeds an answer tolerance of 1e-6: the warning, kind named.
expect_output '"code": "error_estimate", "message": "the error estimate [0-9.e-]+ of dissipation_per_cycle 10\.0[0-9]* \(assumed\) exceeds twice the answer tolerance 1e-06 of it \(the estimate bounds the error at about twice its size\): halve eps and dt, or raise --answer-rtol"' disk --ref-eps 0 --error-estimate one --answer-rtol 1e-6
total=$((total + 1))
if "$sim" disk --ref-eps 0 --error-estimate off | grep -q error_estimate; then
    echo "FAIL: disk --error-estimate off still estimates"; fails=$((fails + 1))
fi
expect_output '"law": "quinn-nested"' disk --law quinn-nested --ref-eps 0
expect_output '"reference": null' disk --ref-eps 0
expect_output '^t,x1,x2,v1,v2,f1,f2$' disk --output trajectory
expect_usage_error "coulomb, force-balance, quinn, quinn-lens, quinn-nested" disk --law lens
expect_usage_error "--a" disk --a 0
expect_usage_error "--ref-eps" disk --ref-eps -1
expect_usage_error "--ref-eps" disk --ref-eps 1e-9
expect_usage_error "--mu" disk --mu 1
# eps beyond the 2-D laws' 1e250 (given, or 2 dt) is named here, not refused by the run with
# exit 1 (fuzz finding of tests/fuzz/fuzz_cli_problems.c).
expect_usage_error "^fricreg-sim: --ref-eps: eps = 1e+308 is outside" disk --ref-eps 1e308
expect_usage_error "^fricreg-sim: --dt: eps = 2e+300 is outside" disk --dt 1e300
expect_usage_error "^fricreg-sim: --eps: eps = 1e+251 is outside" hold --eps 1e251
# COMMAND --help gives each problem's defaults, from the values the parsers use.
expect_output '^  --mu MU +friction coefficient \[0\.5385\]$' hold --help
expect_output '^  --mass KG +the block.s mass, kg \[2\.385\]$' hold --help
expect_output '^  --fs FS .* \[1\]$' belt --help
expect_output '^  --fk FK .* \[0\.5\]$' belt --help
expect_output '^  --vs VS .* \[0\.05\]$' belt --help
expect_output '^  --law coulomb\|force-balance\|quinn\|quinn-lens\|quinn-nested$' disk --help
expect_output '^ +the 2-D friction law .*\[quinn\]$' disk --help
expect_output '^  --a A +forcing amplitude \[2\]$' disk --help
expect_output '^  --omega W +forcing frequency \[0\.5\]$' disk --help
# --help (or -h) anywhere after a subcommand prints that subcommand's help, exit 0 (belt said
# "missing value"); --help alone, the overview naming each command.
for command in oscillator chain twoblock exact reproduce structure hb hold belt disk; do
    expect_output "^usage: fricreg-sim $command " "$command" --help
    expect_output "^  $command +[a-z]" --help
done
expect_output '^  --fs FS' belt --dt 0.01 -h
expect_output '^`fricreg-sim COMMAND --help` lists' --help
expect_output 'man fricreg-sim' --help
expect_usage_error "unknown command" frobnicate --help

# ---- Reliability: no hang, exit codes as the usage says, no data lost ------------------------
# expect NAME COMMAND...: a check that passes when COMMAND (a shell snippet) succeeds.
expect() {
    total=$((total + 1))
    name=$1; shift
    if ! eval "$*"; then
        echo "FAIL: $name: $(cat "$tmp/err" 2>/dev/null)"
        fails=$((fails + 1))
    fi
}
# --cycles nan was converted to int before the check (undefined behaviour; UBSan in the
# sanitize tree); 1e13 is beyond 10^7.
expect_usage_error "^fricreg-sim: --cycles: not a finite number$" oscillator --cycles nan
expect_usage_error "^fricreg-sim: --cycles: must be a whole number" oscillator --cycles 1e13
# Adaptive steps are bounded per cycle (--max-steps; 10^4 for a law that jumps): Coulomb under
# rkf45 chatters at the first stick and stops there (exit 1, the option named), in ~0.05 s.
expect "a chattering adaptive run stops with its reason" \
    '"$sim" oscillator --law coulomb --integrator rkf45 --rtol 1e-6 --atol 1e-8 >"$tmp/out" 2>"$tmp/err"; [ $? -eq 1 ] && [ ! -s "$tmp/out" ] && grep -q "^fricreg-sim: --max-steps: run: more than 10000 adaptive steps (rkf45)" "$tmp/err"'
expect_usage_error "^fricreg-sim: --max-steps: must be a whole number from 0 to 10^9$" oscillator --max-steps -1
expect_output '"steps": 630,' oscillator --max-steps 0 --cycles 1
# Adaptive steps stop at the law's kinks unless --kink-location off, which gives the run of the
# drivers before it: the issue's msbdf run on the two blocks, D on cycle 4 43% off.
expect_output '"kinks": [1-9][0-9]*,' twoblock --integrator msbdf --eps 1e-6 --rtol 1e-6 --atol 1e-6
expect_output '"kinks": 0, .*2.4887871015811562\]' twoblock --integrator msbdf --eps 1e-6 --rtol 1e-6 \
    --atol 1e-6 --kink-location off
expect_usage_error "^fricreg-sim: --kink-location: expected on or off$" oscillator --kink-location 1
# --rtol without --atol: the tolerances from eps (velocities 1e-3 eps, x and D rtol), reported
# per component; the same run's D on cycle 4, 1.7355047, is 4.9e-6 off 1.7355132
# (docs/integrators.md).
expect_output '"atol": "eps", .*"atol_used": \[9.9999999999999995e-07, 9.9999999999999995e-07, 1.0000000000000001e-09, 1.0000000000000001e-09, 9.9999999999999995e-07\]' \
    twoblock --integrator msbdf --eps 1e-6 --rtol 1e-6
expect_output '"dissipation_per_cycle": \[[^]]*, 1\.735504[0-9]*\]' twoblock --integrator msbdf --eps 1e-6 --rtol 1e-6
expect_output '"atol": 1e-08, .*"atol_used": \[1e-08, 1e-08, 1e-08\]' oscillator --integrator rkf45 --rtol 1e-6 --atol 1e-8 --cycles 1
expect_output '"adaptive": false, "dt": 0.01, "rtol": 0, "atol": 0, ' oscillator --cycles 1
# A run length the library refuses is a bad value (exit 2), like the exact solver's.
expect_usage_error "^fricreg-sim: --cycles: run: .* steps is too many" oscillator --cycles 10000000 --dt 1e-4
expect_usage_error "^fricreg-sim: --t-end: run: .* steps is too many" chain --t-end 1e9 --dt 1e-3
# omega = 1e-300 ran for ever: refused at once (the scan step is lost in the rounding of t).
expect_usage_error "^fricreg-sim: --cycles: run: refused at t = .*lost in the rounding of t" exact --omega 1e-300 --a 2 --mun 1 --cycles 1
# An implicit GSL stepper with --atol 0 failed at t = 0 ("GSL stepper failed ... failure").
for i in rk1imp rk2imp rk4imp msadams msbdf; do
    expect_usage_error "^fricreg-sim: --atol: must be > 0 for an implicit GSL stepper" oscillator --integrator $i --rtol 1e-6 --atol 0
done
expect_output '"integrator": "bsimp"' oscillator --integrator bsimp --rtol 1e-6 --atol 0 --cycles 1
# Output that cannot be written: exit 1 with the file named, never 0.
expect "stdout to /dev/full exits 1 naming it" \
    '"$sim" oscillator >/dev/full 2>"$tmp/err"; [ $? -eq 1 ] && grep -q "standard output: No space left" "$tmp/err"'
expect "a trajectory to /dev/full exits 1" \
    '"$sim" oscillator --output trajectory >/dev/full 2>"$tmp/err"; [ $? -eq 1 ] && [ -s "$tmp/err" ]'
# reproduce --out: a file is not a directory (exit 2, as the usage says for a bad --out).
: >"$tmp/plain"
expect_usage_error "^fricreg-sim: --out: .*plain is not a directory$" reproduce --out "$tmp/plain"
# A user's file, or a symlink, with an output's name is never overwritten: refused before
# anything is written, naming it; a rerun into fricreg-sim's own directory replaces its files.
mkdir -p "$tmp/mine" "$tmp/link"
echo "my data" >"$tmp/mine/fig9_chain.csv"
expect_usage_error "^fricreg-sim: --out: .*mine/fig9_chain.csv exists and fricreg-sim did not write it" reproduce --out "$tmp/mine"
expect "the user's file is intact and nothing was written" \
    '[ "$(cat "$tmp/mine/fig9_chain.csv")" = "my data" ] && [ "$(ls -A "$tmp/mine" | wc -l)" -eq 1 ]'
echo "target" >"$tmp/target"
ln -s "$tmp/target" "$tmp/link/fig5_unforced.csv"
expect_usage_error "^fricreg-sim: --out: .*link/fig5_unforced.csv exists .*not a regular file" reproduce --out "$tmp/link"
expect "the symlink's target is intact" '[ "$(cat "$tmp/target")" = "target" ]'
# A file-size limit (16 blocks) truncated every CSV and exited 0: now exit 1 naming the file.
expect "a file-size limit exits 1 naming the file" \
    '(ulimit -f 16 && "$sim" reproduce --out "$tmp/small" >/dev/null 2>"$tmp/err"); [ $? -eq 1 ] && grep -q "small/fig5_unforced.csv: File too large" "$tmp/err" && [ ! -e "$tmp/small/fig5_unforced.csv" ]'
# --out -x: a name like an option made gnuplot's "cd" fail and exited 0 without PNGs. A rerun
# into fricreg-sim's own directory replaces its files. Two full runs, 8 s of the quick tier's
# CPU: with FRICREG_CLI_FULL=1 only (the release tier's cli_full; CI's main job runs one).
if [ "${FRICREG_CLI_FULL:-0}" = 1 ]; then
    expect "reproduce --out -x, twice" \
        '(cd "$tmp" && "$sim" reproduce --out -x >/dev/null 2>"$tmp/err" && "$sim" reproduce --out -x >/dev/null 2>"$tmp/err") && [ -s "$tmp/-x/fig9_chain.csv" ]'
    if command -v gnuplot >/dev/null 2>&1; then
        expect "--out -x gets its PNGs" '[ -s "$tmp/-x/fig5_unforced.png" ] && [ -s "$tmp/-x/fig11_twoblock.png" ]'
    fi
fi

# ---- fit: a joint's parameters from measured levels (fricreg_fit.h). The levels: a modal Iwan
# joint's backbone (F_S 30, K_T 3e5, chi 0.3, beta 0.5, zeta0 0.002, K0 8.4e5; accelerations at
# a sensor of shape 0.37; fricreg_fit_eval, 12 digits), noise-free, with the deviations of
# tests/fit/test_fit.c: the fit recovers every parameter to 1e-9 and each interval holds it.
d=$tmp/fit
mkdir -p "$d"
printf '%s\n' "accel,freq_hz,zeta,sd_freq_hz,sd_zeta" \
    "2,169.851961701,0.00223339284128,0.084926,2.23339e-05" \
    "3.49735724318,169.767329853,0.00248373353687,0.0848837,2.48373e-05" \
    "6.11575384321,169.591486138,0.00300507745189,0.0847957,3.00508e-05" \
    "10.6944880005,169.224220423,0.00409919866067,0.0846121,4.0992e-05" \
    "18.7012225354,168.448543153,0.00643358205117,0.0842243,6.43358e-05" \
    "32.7024280452,166.768877709,0.0116005942518,0.0833844,0.000116006" \
    "57.1860367968,162.487551061,0.0270901181635,0.0812438,0.000270901" \
    "100,154.706618696,0.043470015913,0.0773533,0.0004347" >"$d/levels.csv"
expect_output '"fs": \{"value": (29\.99999999|30\.00000000)[0-9]*, "lower": 29\.[0-9]*, "upper": 30\.[0-9]*, "free": true\}.*"chi": \{"value": 0\.2999999|0\.3000000' \
    fit --levels "$d/levels.csv" --sensor 0.37
expect_output '"beta": \{"value": 0\.5, "lower": 0\.5, "upper": 0\.5, "free": false\}' \
    fit --levels "$d/levels.csv" --sensor 0.37 --fix beta=0.5 --start fs=20
expect_usage_error "^fricreg-sim: --levels: missing$" fit --sensor 0.37
expect_usage_error "^fricreg-sim: --fix: expected NAME=VALUE" fit --levels "$d/levels.csv" --fix mu=0.3
expect_usage_error "^fricreg-sim: --start: a parameter also fixed" fit --levels "$d/levels.csv" --fix beta=0 --start beta=1
expect_usage_error "^fricreg-sim: --sensor: must not be 0" fit --levels "$d/levels.csv" --sensor 0
printf '%s\n' "1,170,0.002" "2,169,0.003,0.1" >"$d/ragged.csv"
expect_usage_error "^fricreg-sim: --levels .*ragged.csv: line 2: 4 numbers: expected 3" fit --levels "$d/ragged.csv"
printf '%s\n' "1,170,-0.002" "2,169,0.003" "3,168,0.004" "4,167,0.005" "5,166,0.006" "6,165,0.007" >"$d/negative.csv"
expect_usage_error "^fricreg-sim: --levels: set_levels: zeta\[0\] = -0.002 is not > 0" fit --levels "$d/negative.csv"
# Eight levels at one amplitude with three free parameters: exit 1, the library's reason.
yes "57.1860367968,162.487551061,0.0270901181635,0.0812438,0.000270901" | head -n 8 >"$d/same.csv"
expect "levels that do not determine the parameters exit 1 with the reason" \
    '"$sim" fit --levels "$d/same.csv" --sensor 0.37 --fix chi=0.3 --fix beta=0.5 --fix zeta0=0.002 >"$d/out" 2>"$d/err"; [ $? -eq 1 ] && [ ! -s "$d/out" ] && grep -q "^fricreg-sim: fit: run: the levels do not determine the parameters" "$d/err"'
expect "--curve writes 100 rows and a header" \
    '"$sim" fit --levels "$d/levels.csv" --sensor 0.37 --curve "$d/curve.csv" >/dev/null 2>"$d/err" && [ "$(head -n 1 "$d/curve.csv")" = "amplitude,freq_hz,zeta,freq_lo,freq_hi,zeta_lo,zeta_hi" ] && [ "$(wc -l <"$d/curve.csv")" -eq 101 ]'

# ---- fit --model hb: a harmonic-balance model's nonlinear mode (fricreg_fit_set_model_hb).
# One unit mass on a unit spring with a Jenkins element kt = 1.7, mu N = 0.26 at H = 1: the
# describing function's closed form (as nma's above), delta = mun/kt, cos(beta) = 1 - 2 delta/a,
# omega^2 = 1 + kt/pi (beta - sin(2 beta)/2), zeta = 4 mun (a - delta)/(2 pi a^2 omega^2), at six
# modal amplitudes past the slip (delta = 0.153). From the driver's values 2x off (kt 3.4,
# mu N 0.13), or the caller's --start with the levels at dof 1 (the unit mass's |X_1| = a), the
# fit recovers both to 1e-6.
d=$tmp/fithb
mkdir -p "$d"
printf '%s\n' "%%MatrixMarket matrix coordinate real symmetric" "1 1 1" "1 1 1" >"$d/M.mtx"
printf '%s\n' "%%MatrixMarket matrix coordinate real general" "1 1 1" "1 1 1" >"$d/J.mtx"
echo "3.4 0.13" >"$d/P_off.txt"
echo "1.7 0.26" >"$d/P.txt"
awk -v kt=1.7 -v mun=0.26 'BEGIN { pi = atan2(0, -1); d = mun / kt; print "a,freq_hz,zeta"
    n = split("0.21 0.33 0.52 0.86 1.37 2.2", A, " ")
    for (i = 1; i <= n; i++) { a = A[i]; c = 1 - 2 * d / a; b = atan2(sqrt(1 - c * c), c)
        w2 = 1 + kt / pi * (b - sin(2 * b) / 2); z = 4 * mun * (a - d) / (2 * pi * a * a * w2)
        printf "%s,%.15g,%.15g\n", a, sqrt(w2) / (2 * pi), z } }' >"$d/levels.csv"
fithb="fit --model hb --levels $d/levels.csv --kind displacement --mass $d/M.mtx --stiffness $d/M.mtx --jenkins $d/J.mtx --harmonics 1 --param element:1:1:1 --param element:1:1:2"
# recovered FILE: the summary's kt and mu N within 1e-6 of 1.7 and 0.26, both free.
recovered() {
    sed -n 's/.*"element:1:1:1": {"value": \([^,]*\),.*"free": true}, "element:1:1:2": {"value": \([^,]*\),.*"free": true}.*/\1 \2/p' "$1" |
        awk '{ e1 = $1 / 1.7 - 1; e2 = $2 / 0.26 - 1; if (e1 < 0) e1 = -e1; if (e2 < 0) e2 = -e2
               ok = NF == 2 && e1 < 1e-6 && e2 < 1e-6 } END { exit !ok }'
}
expect "fit --model hb recovers the Jenkins oscillator's kt and mu N from the driver's values 2x off" \
    '"$sim" $fithb --jenkins-params "$d/P_off.txt" >"$d/off.json" 2>"$tmp/err" && recovered "$d/off.json" && grep -q "\"model\": \"hb\", \"ndof\": 1, \"elements\": 1, \"element_kind\": \"jenkins\", \"mode\": 1, \"harmonics\": 1, .*\"nmodel\": [1-9]" "$d/off.json"'
expect "fit --model hb --dof 1 --start recovers them from the caller's starts 2x off" \
    '"$sim" $fithb --jenkins-params "$d/P.txt" --dof 1 --start 1=3.4 --start 2=0.13 --curve "$d/curve.csv" >"$d/dof.json" 2>"$tmp/err" && recovered "$d/dof.json" && grep -q "\"dof\": 1, " "$d/dof.json" && [ "$(wc -l <"$d/curve.csv")" -eq 101 ]'
expect_output '"element:1:1:1": \{"value": 1\.7, "lower": 1\.7, "upper": 1\.7, "free": false\}, "element:1:1:2": \{"value": 0\.2(5999999|6000000)' \
    $fithb --jenkins-params "$d/P_off.txt" --fix 1=1.7
# The levels hold no viscous damping: a0 runs to its bound 0, exit 1 with the library's reason.
expect "fit --model hb that ends at a bound exits 1 with the reason" \
    '"$sim" $fithb --jenkins-params "$d/P.txt" --param damping:1 >"$d/out" 2>"$tmp/err"; [ $? -eq 1 ] && [ ! -s "$d/out" ] && grep -q "^fricreg-sim: fit: run: Rayleigh a0 ended at its lower bound 0" "$tmp/err"'
# --backbone qsma: QSMA's closed form of the same oscillator (slipping, omega^2 = 1 + mun/a,
# zeta = 4 mun (a - mun/kt)/(2 pi (a + mun) a)) recovered from the driver's values 2x off.
awk -v kt=1.7 -v mun=0.26 'BEGIN { pi = atan2(0, -1); print "a,freq_hz,zeta"
    n = split("0.21 0.33 0.52 0.86 1.37 2.2", A, " ")
    for (i = 1; i <= n; i++) { a = A[i]; z = 4 * mun * (a - mun / kt) / (2 * pi * (a + mun) * a)
        printf "%s,%.15g,%.15g\n", a, sqrt(1 + mun / a) / (2 * pi), z } }' >"$d/qsma.csv"
expect "fit --model hb --backbone qsma recovers kt and mu N from QSMA's closed form" \
    '"$sim" $(echo "$fithb" | sed "s#levels.csv#qsma.csv#") --backbone qsma --jenkins-params "$d/P_off.txt" >"$d/qsma.json" 2>"$tmp/err" && recovered "$d/qsma.json" && grep -q "\"backbone\": \"qsma\"" "$d/qsma.json"'
expect_usage_error "^fricreg-sim: --dof: not with --backbone qsma" $fithb --jenkins-params "$d/P.txt" --backbone qsma --dof 1
expect_usage_error "^fricreg-sim: --backbone: only with --model hb$" fit --levels "$d/levels.csv" --backbone qsma
expect_output '^usage: fricreg-sim fit --levels LEVELS\.csv \[OPTION\]\.\.\. \| --model hb' fit --help
expect_usage_error "^fricreg-sim: --fix: --model hb takes its parameters by position" $fithb --jenkins-params "$d/P.txt" --fix kt=1
expect_usage_error "^fricreg-sim: --start: POSITION=VALUE only with --model hb" fit --levels "$d/levels.csv" --start 1=3
expect_usage_error "^fricreg-sim: --mass: only with --model hb$" fit --levels "$d/levels.csv" --mass "$d/M.mtx"
expect_usage_error "^fricreg-sim: --param: missing" fit --model hb --levels "$d/levels.csv" --mass "$d/M.mtx" --stiffness "$d/M.mtx" --jenkins "$d/J.mtx" --jenkins-params "$d/P.txt"
expect_usage_error "^fricreg-sim: --param: expected element:FIRST:COUNT:INDEX" $fithb --jenkins-params "$d/P.txt" --param element:0:1:1
expect_usage_error "^fricreg-sim: --param: expected element:FIRST:COUNT:INDEX" $fithb --jenkins-params "$d/P.txt" --param damping:0
expect_usage_error "^fricreg-sim: --param: element:2:1:1: elements 2 to 2, but the model has 1$" $fithb --jenkins-params "$d/P.txt" --param element:2:1:1
expect_usage_error "^fricreg-sim: --param: element:1:1:3: element 1 has no parameter 3$" $fithb --jenkins-params "$d/P.txt" --param element:1:1:3
expect_usage_error "^fricreg-sim: --param: element:1:1:2 moves the value of parameter 2 (element:1:1:2) again" $fithb --jenkins-params "$d/P.txt" --param element:1:1:2
expect_usage_error "^fricreg-sim: --fix: position 3 beyond the 2 --param given$" $fithb --jenkins-params "$d/P.txt" --fix 3=1
expect_usage_error "^fricreg-sim: --dof: dof 2 beyond the structure's 1$" $fithb --jenkins-params "$d/P.txt" --dof 2
expect_usage_error "^fricreg-sim: --dof: give --sensor" $fithb --jenkins-params "$d/P.txt" --dof 1 --sensor 2
expect_usage_error "^fricreg-sim: --mode: beyond" $fithb --jenkins-params "$d/P.txt" --mode 2

echo "$((total - fails)) passed, $fails failed"
[ $fails -eq 0 ]
