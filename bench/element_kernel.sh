#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# bench/element_kernel.sh PROGRAM — instructions per point of fricreg-bench-element-kernel's
# items (the hand loop, fricreg_element_eval, fricreg_element_eval_batch) under callgrind:
# the run's total less that of the same run without the item, over 10 sweeps of 1000 points.
set -eu
prog=$1
ir() {
    valgrind --tool=callgrind --callgrind-out-file=/dev/null "$prog" count "$1" "$2" 2>&1 |
        sed -n 's/.*Collected : *\([0-9]*\).*/\1/p'
}
printf '%-12s %8s %8s %8s %8s %8s\n' case hand eval batch eval/h batch/h
for k in 0 1 2; do
    none=$(ir $k none)
    h=$(( ($(ir $k hand) - none) / 10000 ))
    e=$(( ($(ir $k eval) - none) / 10000 ))
    b=$(( ($(ir $k batch) - none) / 10000 ))
    name=$(echo "jenkins contact_3d iwan" | cut -d' ' -f$((k + 1)))
    awk -v n="$name" -v h=$h -v e=$e -v b=$b \
        'BEGIN { printf "%-12s %8d %8d %8d %8.2f %8.2f\n", n, h, e, b, e / h, b / h }'
done
