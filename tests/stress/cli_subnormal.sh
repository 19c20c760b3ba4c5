#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# Subnormal values on fricreg-sim's command line (1.0 refused them).
# Values below DBL_MIN are ordinary finite numbers: every system and the exact solver take
# them and print finite results; only eps, which the library requires >= DBL_MIN (2/eps would
# overflow), is refused, non-zero, with a message that says why.
#   usage: cli_subnormal.sh FRICREG-SIM
set -u
sim=$1
fail=0
out=$(mktemp) && err=$(mktemp) || exit 1
trap 'rm -f "$out" "$err"' EXIT

accepts() {
    if "$sim" "$@" --cycles 1 >"$out" 2>"$err" && ! grep -qi 'nan\|inf' "$out"; then
        echo "ok: $*"
    else
        echo "FAIL: $* refused or not finite: $(cat "$err") $(head -c 300 "$out")"
        fail=1
    fi
}

accepts oscillator --mun 1e-310 --x0 4.9e-324 --v0 -5e-324 --a 1e-320
accepts twoblock --mu1 1e-310 --mu2 2e-315 --belt-amp 3e-310
accepts chain --n 2 --a 1e-310
accepts exact --mun 3e-310 --x0 1e-315 --a 2e-320

if "$sim" oscillator --eps 1e-310 --cycles 1 >"$out" 2>"$err"; then
    echo "FAIL: --eps 1e-310 accepted"
    fail=1
elif grep -q 'DBL_MIN' "$err"; then
    echo "ok: --eps 1e-310 refused: $(cat "$err")"
else
    echo "FAIL: --eps 1e-310 refused without saying why: $(cat "$err")"
    fail=1
fi
exit $fail
