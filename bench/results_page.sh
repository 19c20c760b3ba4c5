#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# bench/results_page.sh — writes the dated results page (docs/results.md) from the files the
# benchmark leaves in its results folder: machine.txt, summary.csv, orders.csv, scaling.csv
# and laws.csv. bench/run.sh calls it last; the numbers live in that page and nowhere else.
# Usage: results_page.sh RESULTS_DIR OUT.md
set -eu
dir=$1 out=$2
for f in machine.txt summary.csv orders.csv scaling.csv laws.csv; do
    [ -f "$dir/$f" ] || { echo "results_page.sh: $dir/$f is missing" >&2; exit 1; }
done
field() { sed -n "s/^$1: //p" "$dir/machine.txt"; }

# Rows in order of first appearance, columns by problem; one cell per (row, problem).
pivot() { # CSV HEADER_CELL PROBLEM_HEADER_SUFFIXES AWK_CELL_EXPRESSION
    awk -F, -v sufs="$3" -v first="$2" '
    NR == 1 { next }
    {
        if (!($2 in seen)) { seen[$2] = 1; rows[++nr] = $2 }
        if (!($1 in pseen)) { pseen[$1] = 1; probs[++np] = $1 }
        cell[$2, $1] = '"$4"'
    }
    END {
        ns = split(sufs, s, "|")
        if (ns == 0) { ns = 1; s[1] = "" }
        line = "| " first " |"; rule = "|---|"
        for (p = 1; p <= np; p++) for (k = 1; k <= ns; k++) {
            line = line " " probs[p] (s[k] == "" ? "" : " " s[k]) " |"; rule = rule "---|"
        }
        print line; print rule
        for (r = 1; r <= nr; r++) {
            line = "| " rows[r] " |"
            for (p = 1; p <= np; p++) {
                if (!((rows[r], probs[p]) in cell)) {
                    for (k = 1; k <= ns; k++) line = line " n/a |"
                    continue
                }
                split(cell[rows[r], probs[p]], parts, "\t")
                for (k = 1; k <= ns; k++) line = line " " parts[k] " |"
            }
            print line
        }
    }' "$1"
}

{
    echo "# Benchmark results"
    echo
    echo "Written by \`bench/run.sh\` (\`bench/results_page.sh\`) on $(field date), at commit"
    echo "$(field commit), on this machine:"
    echo
    echo "    $(field machine)"
    echo
    echo "CPU times vary with the machine and its load: compare the ratios, and rerun"
    echo "\`bench/run.sh\` to refresh this page. The method, and what the first run found, are in"
    echo "[benchmark.md](benchmark.md)."
    echo
    echo "## CPU seconds to reach 1% and 0.01% relative error in D"
    echo
    echo "The cheapest point from which every finer point of the sweep stays below the target; \`<=\`:"
    echo "reached already at the coarsest point; \`-\`: never within the sweep; in brackets the ratio"
    echo "to RK4 + (4) Quinn on the same problem (\`~\`: a ratio involving a \`<=\` bound); n/a: not run."
    echo
    pivot "$dir/summary.csv" method "1%|0.01%" '$3 " (" $4 ")\t" $5 " (" $6 ")"' | sed 's/ (-)//g'
    echo
    echo "## Observed order in Δt"
    echo
    echo "RK4 with the paper's ε rules: the least-squares slope of log error against log Δt over the"
    echo "asymptotic range | over the whole sweep."
    echo
    pivot "$dir/orders.csv" method "" 'sprintf("%.2f \\| %.2f", $3, $5)'
    echo
    echo "## Scaling: the chain, RK4, Δt = 0.35/n, from rest"
    echo
    echo "| n | steps | ns per step per block, (4) | (1) | (4)/(1) |"
    echo "|---|---|---|---|---|"
    awk -F, 'NR > 1 { printf "| %s | %s | %.1f | %.1f | %.2f |\n", $1, $2, $3, $4, $5 }' "$dir/scaling.csv"
    echo
    echo "## The laws alone: ns per contact"
    echo
    echo "Contacts 40% stuck, 20% near stick, 40% slipping."
    echo
    echo "| law | path | m | ns per contact |"
    echo "|---|---|---|---|"
    awk -F, 'NR > 1 { printf "| %s | `%s` | %s | %.2f |\n", $1, $2, $3, $4 }' "$dir/laws.csv"
} >"$out"
echo "results page: $out"
