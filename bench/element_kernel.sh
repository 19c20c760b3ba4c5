#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# bench/element_kernel.sh PROGRAM — instructions per point of fricreg-bench-element-kernel's
# items under callgrind, each library item beside its hand item (bench/element_kernel.c): the
# run's total less that of the same run without the item, over 10 sweeps of 1000 points.
set -eu
prog=$1
ir() {
    valgrind --tool=callgrind --callgrind-out-file=/dev/null "$prog" count "$1" "$2" 2>&1 |
        sed -n 's/.*Collected : *\([0-9]*\).*/\1/p'
}
printf '%-11s %6s %6s %7s %7s %6s %6s %8s %8s %8s\n' case loop batch loop_s batch_s point eval \
    batch/h batch_s/h eval/h
for k in 0 1 2; do
    none=$(ir $k none)
    line=""
    for item in hand batch hand_shared batch_shared hand_point eval; do
        line="$line $(( ($(ir $k $item) - none) / 10000 ))"
    done
    name=$(echo "jenkins contact_3d iwan" | cut -d' ' -f$((k + 1)))
    echo "$name $line" | awk '{ printf "%-11s %6d %6d %7d %7d %6d %6d %8.2f %8.2f %8.2f\n",
        $1, $2, $3, $4, $5, $6, $7, $3 / $2, $5 / $4, $7 / $6 }'
done
