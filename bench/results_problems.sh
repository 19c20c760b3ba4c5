#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# bench/results_problems.sh — prints the results page's section on the three problems beyond
# the paper (Markdown, to stdout) from the files fricreg-bench-problems leaves in the results
# folder: problems_hold.csv, and with SUNDIALS problems_best.csv and problems_refs.csv.
# bench/results_page.sh appends it to docs/results.md; prints nothing if the benchmark did not
# run.
# Usage: results_problems.sh RESULTS_DIR
set -eu
dir=$1
[ -f "$dir/problems_hold.csv" ] || exit 0

echo
echo "## Beyond the paper: the belt, the 2-D oscillator, the hold"
echo
echo "\`fricreg-bench-problems\` (method: [benchmark.md](benchmark.md#the-problems-beyond-the-paper))."
echo "CPU seconds are medians of 3 interleaved passes; errors are relative, against event-driven"
echo "CVODE Adams at rtol 1e-12."
if [ -f "$dir/machine.txt" ]; then
    echo "This section's run: $(sed -n 's/^date: //p' "$dir/machine.txt"), commit"
    echo "$(sed -n 's/^commit: //p' "$dir/machine.txt"); $(sed -n 's/^machine: //p' "$dir/machine.txt")"
    echo "(a load average above the number of CPUs: a shared, loaded machine; read the ratios, not"
    echo "the seconds)."
fi
if [ ! -f "$dir/problems_best.csv" ]; then
    echo
    echo "The belt and the 2-D oscillator were not run: their references need SUNDIALS CVODE."
else
    echo
    echo "CPU seconds to reach each target: the cheapest point of a method's sweep from which every"
    echo "finer point stays below the target (\`<=\`: already at the coarsest point, \`-\`: never"
    echo "within the sweep). Belt: the larger of the period's and the amplitude's errors; disk: D per"
    echo "forcing cycle. RK4 rows are fricreg's laws under GSL's fixed-step RK4 with ε = 2Δt; cvode rows"
    echo "the event-driven references over rtol = 1e-3 … 1e-11."
    for p in belt disk; do
        echo
        awk -F, -v p="$p" '
        NR == 1 {
            for (k = 5; k <= NF; k++) { split($k, w, " "); if (w[1] == p) { col[++n] = k; name[n] = w[2] } }
            line = "| " p " target | winner |"; rule = "|---|---|"
            for (j = 1; j <= n; j++) { line = line " " name[j] " |"; rule = rule "---|" }
            print line; print rule; next
        }
        $1 == p {
            line = "| " $2 " | **" $3 "** |"
            for (j = 1; j <= n; j++) line = line " " $(col[j]) " |"
            print line
        }' "$dir/problems_best.csv"
    done
fi
if [ -f "$dir/problems_refs.csv" ]; then
    echo
    echo "The references' convergence: relative difference to Adams at rtol 1e-12 (belt: the larger of"
    echo "period and amplitude), with the steps taken."
    echo
    echo "| rtol | belt Adams | belt BDF | disk Adams | disk BDF |"
    echo "|---|---|---|---|---|"
    awk -F, 'NR > 1 { c[$3, $1 " " $2] = sprintf("%.1e (%d)", $8, $6); if (!($3 in s)) { s[$3] = 1; r[++n] = $3 } }
    END { for (i = 1; i <= n; i++) printf "| %s | %s | %s | %s | %s |\n", r[i], c[r[i], "belt adams"],
          c[r[i], "belt bdf"], c[r[i], "disk adams"], c[r[i], "disk bdf"] }' "$dir/problems_refs.csv"
fi
echo
echo "The hold: a block on an incline (tan θ = 0.8 μ), from rest, 10⁶ GSL RK4 steps of 1e-4 s,"
echo "ε = 20Δt: creep |x(T) − x(0)|/T, the largest speed, and CPU seconds per 10⁶ steps."
echo
echo "| 2-D law | creep m/s | max \|v\| m/s | CPU s per 10⁶ steps |"
echo "|---|---|---|---|"
awk -F, 'NR > 1 { printf "| %s | %.3g | %.3g | %.3f |\n", $1, $4, $5, $6 }' "$dir/problems_hold.csv"
