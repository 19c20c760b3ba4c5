#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# bench/structure_scaling.sh — a structure's Newmark step against its size (method:
# docs/benchmark.md#a-structures-step-against-its-size): fricreg-bench-structure-scaling over
# n = 10^2 ... 10^6 degrees of freedom with k = 1, sqrt(n), 10^3 and n/2 contacts, each size
# in a process of its own (its peak memory is its own), beside the frictionless Newmark step on
# the same factor; then the growth exponents, least squares on log t against log n over
# 10^3 ... 10^6. Writes OUT/structure_scaling.csv and prints a Markdown table.
# Usage: structure_scaling.sh BENCH_BINARY OUT_DIR [MAX_N]
set -eu
bin=$1 out=$2 max=${3:-1000000}
csv=$out/structure_scaling.csv
echo "n,k,steps,setup_s,step_s,linear_step_s,ratio,newton_mean,peak_mib" >"$csv"
for n in 100 1000 10000 100000 1000000; do
    [ "$n" -le "$max" ] || continue
    root=$(awk -v n="$n" 'BEGIN { printf "%d", sqrt(n) + 0.5 }')
    # fewer steps at the largest sizes: a step is then tens of milliseconds
    steps=$(awk -v n="$n" 'BEGIN { print (n >= 1000000 ? 5 : (n >= 100000 ? 10 : 20)) }')
    done_k=" "
    for k in 1 "$root" 1000 $((n / 2)); do
        [ "$k" -le $((n / 2)) ] || continue
        case $done_k in *" $k "*) continue ;; esac # sqrt(10^6) is 10^3: once
        done_k="$done_k$k "
        line=$("$bin" "$n" "$k" "$steps" 3) || { echo "n = $n, k = $k failed" >&2; continue; }
        echo "$line" | tr ' ' ',' >>"$csv"
    done
done

echo "| n | k | set-up (s) | step (ms) | frictionless step (ms) | ratio | Newton/step | peak (MiB) |"
echo "|---:|---:|---:|---:|---:|---:|---:|---:|"
awk -F, 'NR > 1 { printf "| %d | %d | %.3g | %.3g | %.3g | %.2f | %.2f | %.0f |\n",
                  $1, $2, $4, 1e3 * $5, 1e3 * $6, $7, $8, $9 }' "$csv" | sort -t'|' -k2,2n -k3,3n
echo
echo "Growth exponents of the step's time over n = 10^3 ... 10^6 (least squares on the logs):"
for kind in one root thousand half; do
    awk -F, -v kind="$kind" '
        NR > 1 && $1 >= 1000 {
            root = int(sqrt($1) + 0.5)
            if ((kind == "one" && $2 == 1) || (kind == "root" && $2 == root && $2 != 1000) ||
                (kind == "thousand" && $2 == 1000) || (kind == "half" && 2 * $2 == $1)) {
                x = log($1); y = log($5); z = log($6)
                n++; sx += x; sy += y; sz += z; sxx += x * x; sxy += x * y; sxz += x * z
            }
        }
        END {
            if (n < 2) exit
            d = n * sxx - sx * sx
            printf "- k = %s: %.2f (frictionless step: %.2f), %d sizes\n",
                   kind == "one" ? "1" : kind == "root" ? "sqrt(n)" : kind == "thousand" ? "10^3" : "n/2",
                   (n * sxy - sx * sy) / d, (n * sxz - sx * sz) / d, n
        }' "$csv"
done
