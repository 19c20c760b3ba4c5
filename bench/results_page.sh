#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# bench/results_page.sh — writes the dated results page (docs/results.md) from the files the
# benchmark leaves in its results folder: machine.txt, best.csv, summary.csv, orders.csv,
# scaling.csv and laws.csv. bench/run.sh calls it last; the numbers live in that page and nowhere else.
# Usage: results_page.sh RESULTS_DIR OUT.md
set -eu
dir=$1 out=$2
for f in machine.txt best.csv summary.csv orders.csv scaling.csv laws.csv; do
    [ -f "$dir/$f" ] || { echo "results_page.sh: $dir/$f is missing" >&2; exit 1; }
done
field() { sed -n "s/^$1: //p" "$dir/machine.txt"; }
# verbatim TITLE FILE: a section holding a benchmark's printed output as it stands, if it ran.
verbatim() {
    [ -f "$dir/$2" ] || return 0
    printf '\n## %s\n\n`%s` as printed:\n\n```\n' "$1" "$2"
    cat "$dir/$2"
    printf '```\n'
}

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
    echo "\`bench/run.sh\` to refresh this page. The method, and how to read these tables, are in"
    echo "[benchmark.md](benchmark.md)."
    echo
    echo "## Against event-driven CVODE, relative error 1e-2 … 1e-8 in D"
    echo
    echo "Per problem and target: fricreg's cheapest method (law (4) with any integrator, with or"
    echo "without extrapolation in ε) and its CPU seconds, then event-driven CVODE's (classical"
    echo "Coulomb, Adams and BDF) and the ratio CVODE / fricreg, all from this run: **above 1,"
    echo "fricreg is ahead**. \`never\`: CVODE does not reach the target within its sweep; \`~\`:"
    echo "a \`<=\` bound is involved; n/a: not run (the two blocks' contacts are coupled). Each"
    echo "side at its best: the cheapest of its configurations to reach the target, named in the"
    echo "\`at\` columns (fricreg's Δt or tolerance; CVODE's rtol and atol)."
    echo
    echo "| problem | target | fricreg's best | at | CPU s | CVODE Adams | at | Adams / fricreg | CVODE BDF | at | BDF / fricreg |"
    echo "|---|---|---|---|---|---|---|---|---|---|---|"
    awk -F, 'NR > 1 {
        if ($3 ~ /^not judged/) { printf "| %s | %s | %s | | | | | | | | |\n", $1, $2, $3; next }
        printf "| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n", $1, $2, $3, $9, $4,
               $5, $10, $6, $7, $11, $8 }' "$dir/best.csv"
    echo
    awk -F, 'NR > 1 && $3 !~ /^not judged/ {
        for (k = 6; k <= 8; k += 2) {
            r = $k; sub(/^~/, "", r)
            if (r == "-" || (r ~ /^[0-9.e+-]+$/ && r + 0 < 1))
                below = below sprintf("%s%s at %s against %s (%s)", below == "" ? "" : "; ", $1,
                                      $2, k == 6 ? "Adams" : "BDF", $k)
            else if (r ~ /^[0-9.e+-]+$/ && r + 0 < 2)
                below2 = below2 sprintf("%s%s at %s against %s (%s)", below2 == "" ? "" : "; ",
                                        $1, $2, k == 6 ? "Adams" : "BDF", $k)
        }
    }
    END {
        if (below == "") print "Every judged cell is above 1."
        else print "**Cells still below 1** (or not reached by fricreg: `-`): " below "."
        if (below2 != "") print "\nCells between 1 and 2: " below2 "."
    }' "$dir/best.csv"
    echo
    echo "## The chain at n = 1000 (and 10⁴) against CVODE Adams"
    echo
    if [ -f "$dir/bigchain.csv" ]; then
        echo "D on cycle 1 (\`fricreg-bench-bigchain\`, one run each). No independent reference exists"
        echo "at this size: the errors are against the first row of each n, law (4) + RK4 extrapolated"
        echo "in ε over three levels (itself flagged or not as its ratios say), and above n = 2000"
        echo "RK4 at the guard's step alone. Two prototypes in bench/, not the library, each O(n) a"
        echo "step: \`newmark-tridiag\` (Newmark, Newton on the chain's tridiagonal matrix) and"
        echo "\`central-diff\` (explicit central differences, one friction evaluation a step). CVODE"
        echo "runs stop at a CPU cap (the note says how far they got). BDF (dense Newton on 2n + 1"
        echo "unknowns) is not run."
        echo
        echo "| n | method | Δt or rtol | CPU s | relative error | note |"
        echo "|---|---|---|---|---|---|"
        awk -F, 'NR > 1 {
            note = $8; gsub(/"/, "", note)
            err = $7 == 0 ? sprintf("%.1e", $6) : "failed"
            printf "| %s | %s | %s | %.3g | %s | %s |\n", $1, $2, $3, $4, err, note }' \
            "$dir/bigchain.csv"
    else
        echo "Not run in this run: \`FRICREG_BENCH_BIG=1 bench/run.sh\` (minutes of CPU)."
    fi
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
    verbatim "The kernels against the minimal loop and the triad bandwidth" kernels.txt
    verbatim "Dense W, m = 500: a changing near-stick set against an unchanged one" dense.txt
    verbatim "The 2-D context on stuck chains, beside the 1-D context" disk_chain.txt
    sh "$(dirname "$0")/results_problems.sh" "$dir" # if fricreg-bench-problems ran
} >"$out"
echo "results page: $out"
