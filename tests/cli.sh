#!/bin/sh
# fricreg-sim's command line: usage errors exit 2 with one line naming the option and write
# nothing to stdout; runs print the paper's numbers. Usage: cli.sh PATH/TO/fricreg-sim
sim=$1
fails=0
total=0
tmp=${TMPDIR:-/tmp}/fricreg-cli.$$
mkdir -p "$tmp"
trap 'rm -rf "$tmp"' EXIT

# expect_usage_error OPTION-NAMED-IN-MESSAGE ARGS...
expect_usage_error() {
    total=$((total + 1))
    named=$1; shift
    "$sim" "$@" >"$tmp/out" 2>"$tmp/err"
    rc=$?
    if [ $rc -ne 2 ] || [ -s "$tmp/out" ] || [ "$(wc -l <"$tmp/err")" -ne 1 ] ||
       ! grep -q -- "$named" "$tmp/err"; then
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

expect_usage_error "unknown command" frobnicate
expect_usage_error "--dt" oscillator --dt -1
expect_usage_error "--dt" oscillator --dt 0
expect_usage_error "--dt" oscillator --dt nan
expect_usage_error "--dt" oscillator --dt inf
expect_usage_error "--dt" oscillator --dt 1e999
expect_usage_error "--dt" oscillator --dt 0.01x
expect_usage_error "--eps" oscillator --eps -0.1
expect_usage_error "--law" oscillator --law sticky
# The valid names come from the library (fricreg_law_name, fricreg_integrator_name).
expect_usage_error "coulomb, force-balance, karnopp, velocity-limited, tanh, quinn" oscillator --law Quinn
expect_usage_error "rk2, rk4, rkf45, rkck, rk8pd, rk1imp, rk2imp, rk4imp, bsimp, msadams, msbdf" chain --integrator rk45
expect_output '^  --law coulomb\|force-balance\|karnopp\|velocity-limited\|tanh\|quinn +\[quinn\]$' --help
expect_output '^  --integrator rk2\|rk4\|rkf45\|rkck\|rk8pd\|rk1imp\|rk2imp\|rk4imp\|bsimp\|msadams\|msbdf\|rk4-gsl \[rk4\]$' --help
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
expect_usage_error "--a" oscillator --a
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
# reversal within one step is refused beyond dt * omega = 1/sqrt 2 (src/sim.c).
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

echo "$((total - fails)) passed, $fails failed"
[ $fails -eq 0 ]
