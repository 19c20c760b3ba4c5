#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# bench/readme_table.sh DIR README — the work-precision summary the README quotes: per
# problem and target error, CVODE's CPU over fricreg's best (Adams / BDF; above 1, fricreg is
# ahead), from DIR/best.csv (fricreg-bench-wp), written between README's two marker lines
# "<!-- results:begin -->" and "<!-- results:end -->". Run by bench/run.sh.
set -eu
dir=$1
readme=$2
[ -f "$dir/best.csv" ] || { echo "readme_table.sh: no $dir/best.csv" >&2; exit 1; }
table=$(mktemp)
trap 'rm -f "$table"' EXIT
{
    echo "<!-- results:begin -->"
    echo "| CVODE / fricreg (Adams, BDF) | 1e-2 | 1e-3 | 1e-4 | 1e-5 | 1e-6 | 1e-7 | 1e-8 |"
    echo "|---|---|---|---|---|---|---|---|"
    awk -F, 'NR > 1 {
        if (!($1 in seen)) { seen[$1] = 1; order[++n] = $1 }
        cell = ($3 ~ /^not judged/) ? "not judged" : ($6 == "n/a" ? "n/a" : $6 ", " $8)
        row[$1] = row[$1] " | " cell
    }
    END { for (k = 1; k <= n; k++) print "| " order[k] row[order[k]] " |" }' "$dir/best.csv"
    echo "<!-- results:end -->"
} >"$table"
awk -v table="$table" '
    /^<!-- results:begin -->$/ { while ((getline line < table) > 0) print line; skip = 1; next }
    /^<!-- results:end -->$/ { skip = 0; next }
    !skip { print }' "$readme" >"$readme.new"
mv "$readme.new" "$readme"
