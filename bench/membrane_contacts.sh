#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# bench/membrane_contacts.sh — coupled contacts on a continuum (method:
# docs/benchmark.md#coupled-contacts-on-a-continuum): fricreg-bench-membrane-contacts on the
# 316 x 316 membrane (10^5 dofs) with its edge row alone and with two coupled rows, at three
# spring stiffnesses (W_eff of the edge banded at 10^4 N/m, mostly dense at 3e6 and 1e7), and
# with eight rows (2528 contacts) at 3e6 in each of the bench's four layouts (stacked from the
# edge, stacked in the middle, spread over the membrane, each row against the ground), each in
# a process of its own with both near-stick
# solvers (dense and sparse, against one frictionless run), 2 s of shaking (400 steps); with
# FRICREG_BENCH_BIG=1 also the 1000 x 1000 membrane (10^6 dofs) with ten rows (10^4
# contacts), 10 steps at 10^4 N/m and 40 steps at 3e6 (minutes: the stiff set-up forms a
# dense 10^4 x 10^4 W_eff).
# Writes OUT/membrane_contacts.csv and prints a Markdown table.
# Usage: membrane_contacts.sh BENCH_BINARY OUT_DIR
set -eu
bin=$1 out=$2
csv=$out/membrane_contacts.csv
echo "spring_k,n,m,steps,run_s,linear_run_s,run_ratio,step_s,linear_step_s,step_ratio,newton_mean,stuck_fraction,peak_mib,path,layout" >"$csv"
run() { # N ROWS STEPS REPEATS K [LAYOUT]: one line a path
    layout=${6:-stacked}
    lines=$("$bin" "$1" "$2" "$3" "$4" "$5" both "$layout") || { echo "N = $1, rows = $2, K = $5, $layout failed" >&2; return; }
    printf '%s\n' "$lines" | sed "s/^/$5 /; s/\$/ $layout/" | tr ' ' ',' >>"$csv"
}
for k in 1e4 3e6 1e7; do
    run 316 1 400 8 "$k"
    run 316 2 400 8 "$k"
done
for layout in stacked interior spread grounded; do
    run 316 8 400 8 3e6 "$layout"
done
if [ "${FRICREG_BENCH_BIG:-0}" = 1 ]; then
    run 1000 10 10 5 1e4
    run 1000 10 40 5 3e6
fi

echo "| K (N/m) | n | contacts | layout | path | whole run (s) | frictionless run (s) | ratio | step (ms) | frictionless step (ms) | ratio | Newton/step | stuck | peak (MiB) |"
echo "|---:|---:|---:|:---|:---|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
awk -F, 'NR > 1 { printf "| %s | %d | %d | %s | %s | %.3g | %.3g | %.2f | %.3g | %.3g | %.2f | %.2f | %.2f | %.0f |\n",
                  $1, $2, $3, $15, $14, $5, $6, $7, 1e3 * $8, 1e3 * $9, $10, $11, $12, $13 }' "$csv"
