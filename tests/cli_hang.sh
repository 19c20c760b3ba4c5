#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The hang sweep: fricreg-sim on settings that ask for unbounded or absurd work (laws that jump
# under adaptive steppers, tolerances far below the law's kinks, belts too fast or too slow
# for stick-slip, runs of more steps than a machine does in hours) must each end within
# LIMIT seconds of CPU: finished (exit 0), or refused or stopped with its reason on stderr
# (exit 1 or 2). CPU time, not the clock's (ulimit -t): a command that spins is stopped at the
# limit however loaded the machine, and one that waits is stopped by the clock at 6 times it.
# Either is a failure. The seven runs that work for seconds before they end (run_long, 20 s of
# the sweep's 22) run with FRICREG_CLI_LONG=1 only (the release tier's cli_hang_release); the
# others, a command or more of each kind, in the quick tier.
# Usage: cli_hang.sh PATH/TO/fricreg-sim [LIMIT]
sim=$1 limit=${2:-10}
tmp=$(mktemp -d "${TMPDIR:-/tmp}/fricreg-hang.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
command -v timeout >/dev/null 2>&1 || { echo "timeout(1) not found: skipped"; exit 77; }

# A structure of two storeys on the ground, for the structure runs.
d=$tmp/model
mkdir -p "$d"
printf '%%%%MatrixMarket matrix coordinate real symmetric\n2 2 2\n1 1 1.7\n2 2 0.9\n' >"$d/M.mtx"
printf '%%%%MatrixMarket matrix coordinate real symmetric\n2 2 3\n1 1 30.2\n2 1 -12.1\n2 2 12.1\n' >"$d/K.mtx"
printf '%%%%MatrixMarket matrix coordinate real general\n2 2 3\n1 1 1\n2 1 -1\n2 2 1\n' >"$d/J.mtx"
printf '0.4\n0.3\n' >"$d/mun.txt"
printf '# t a_g\n0 0\n0.5 2.41\n1 -1.3\n30 0.7\n' >"$d/ag.txt"
structure="structure --mass $d/M.mtx --stiffness $d/K.mtx --contacts $d/J.mtx --mun $d/mun.txt --ground-accel $d/ag.txt"

fails=0 total=0 slowest=0
run() { # ARGS...: one command within the limit, a reason on stderr unless it succeeded
    total=$((total + 1))
    start=$(date +%s)
    # shellcheck disable=SC2086 # the arguments are words
    timeout $((6 * limit)) sh -c 'ulimit -t "$1" && shift && exec "$@"' sh "$limit" "$sim" "$@" \
        >"$tmp/out" 2>"$tmp/err"
    rc=$?
    took=$(($(date +%s) - start))
    [ "$took" -gt "$slowest" ] && slowest=$took
    if [ $rc -eq 124 ]; then
        echo "FAIL (waited more than $((6 * limit)) s): fricreg-sim $*"
        fails=$((fails + 1))
    elif [ $rc -eq 152 ] || [ $rc -eq 137 ]; then # SIGXCPU, or SIGKILL at the hard limit
        echo "FAIL (more than ${limit} s of CPU): fricreg-sim $*"
        fails=$((fails + 1))
    elif [ $rc -ne 0 ] && [ ! -s "$tmp/err" ]; then
        echo "FAIL (exit $rc, no reason): fricreg-sim $*"
        fails=$((fails + 1))
    elif [ $rc -gt 2 ]; then
        echo "FAIL (exit $rc): fricreg-sim $*: $(cat "$tmp/err")"
        fails=$((fails + 1))
    fi
}
run_long() { # ARGS...: as run, with FRICREG_CLI_LONG=1 only
    [ "${FRICREG_CLI_LONG:-0}" = 1 ] && run "$@"
}

# Laws that jump under adaptive steppers: bounded by --max-steps (10^6 a cycle).
run oscillator --law coulomb --integrator rkf45 --rtol 1e-6 --atol 1e-8
run oscillator --law force-balance --integrator rkf45 --rtol 1e-9 --atol 1e-12
run oscillator --law karnopp --integrator rk8pd --rtol 1e-10 --atol 1e-12
run oscillator --law coulomb --integrator msadams --rtol 1e-6 --atol 1e-8
run oscillator --law coulomb --integrator bsimp --rtol 1e-10 --atol 1e-12
run chain --n 32 --law coulomb --integrator rkck --rtol 1e-8 --atol 1e-10
run_long chain --n 32 --law force-balance --integrator msbdf --rtol 1e-6 --atol 1e-8
run twoblock --law coulomb --integrator rkf45 --rtol 1e-8 --atol 1e-10
run twoblock --law karnopp --integrator rkf45 --rtol 1e-6 --atol 1e-8
# Tolerances and eps far below the scale of the motion.
run_long oscillator --law velocity-limited --eps 5.5e-6 --integrator msadams --rtol 1e-6 --atol 1e-8
run_long oscillator --eps 1e-9 --integrator rkf45 --rtol 1e-6 --atol 1e-8
run oscillator --eps 1e-8 --integrator msbdf --rtol 1e-12 --atol 1e-14
run oscillator --eps 1e-8 --integrator rk4imp --rtol 1e-12 --atol 1e-14
run_long twoblock --eps 1e-9 --integrator rk8pd --rtol 1e-12 --atol 1e-14
# Run lengths beyond reason: refused before the first step.
run oscillator --omega 1e-9
run oscillator --t-end 1e12 --integrator rkf45 --rtol 1e-3 --atol 1e-3
run oscillator --cycles 10000000 --dt 1e-4
run chain --n 1000000 --cycles 1
run twoblock --k 1e12
run exact --cycles 10000000
run exact --mun 1e-300 --a 1e300
# The reference problems beyond the paper.
run_long belt --v-belt 1e3
run belt --v-belt 1e-6
run_long belt --vs 1e-9
run_long belt --delta 0.01 --cycles 20
run belt --fs 1e6 --fk 0
run hold --tilt-rate 1e-9
run hold --tilt-rate 1e6
run disk --dt 1e-7
run disk --ref-eps 1e-12
# Structures: adaptive steps bounded by --max-steps over the whole run; fixed ones in advance.
run $structure --law coulomb --integrator rkf45 --rtol 1e-6 --atol 1e-8 --dt 0.01 --t-end 30
run $structure --law force-balance --integrator msbdf --rtol 1e-9 --atol 1e-12 --dt 0.01 --t-end 30
run $structure --eps 1e-9 --integrator rk8pd --rtol 1e-12 --atol 1e-14 --dt 0.01 --t-end 30
run $structure --integrator newmark --dt 1e-9 --t-end 30

echo "$((total - fails)) passed, $fails failed; the slowest took ${slowest} s of the clock (limit ${limit} s of CPU)"
[ $fails -eq 0 ]
