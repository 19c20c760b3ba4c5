#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# run.sh — the ten-storey building (docs/structural.md) from the command line: writes its files with
# make_building into DIR, runs fricreg-sim structure on them and prints the JSON summary, then
# one line with the numbers docs/structural.md quotes. Options after DIR are passed on and
# replace the defaults (Newmark, dt = 0.01 s, eps = 0.01 m/s, 15 s): a default is passed only
# when they do not give its option, since fricreg-sim refuses an option given twice.
#   usage: run.sh PATH/TO/fricreg-sim PATH/TO/make_building DIR [fricreg-sim options...]
sim=$1; make_building=$2; dir=$3
shift 3 || { echo "usage: run.sh fricreg-sim make_building DIR [options]" >&2; exit 2; }
mkdir -p "$dir" && "$make_building" "$dir" || exit 1
defaults=
for default in "--eps 0.01" "--integrator newmark" "--dt 0.01" "--t-end 15"; do
    case " $* " in
        *" ${default%% *} "* | *" ${default%% *}="*) ;;
        *) defaults="$defaults $default" ;;
    esac
done
# shellcheck disable=SC2086 # the defaults are words without spaces
"$sim" structure --mass "$dir/M.mtx" --stiffness "$dir/K.mtx" \
    --rayleigh "$(cat "$dir/rayleigh.txt")" --contacts "$dir/J.mtx" --mun "$dir/mun.txt" \
    --ground-accel "$dir/ground.txt" $defaults "$@" >"$dir/summary.json" || exit 1
cat "$dir/summary.json"
# peak roof displacement (m), damper energy (J), Newton mean and max, failures, residual/input
sed -e 's/.*"peak_displacement": \[[^]]*, \([^],]*\)\].*"dissipation_per_contact": \[\([^]]*\)\].*"input": \([^,]*\),.*"residual": \([^}]*\)}, "newton_iterations": {"mean": \([^,]*\), "max": \([^}]*\)}, "newton_failures": \([0-9]*\), "cpu_seconds": \([0-9.]*\).*/\1 \2 \3 \4 \5 \6 \7 \8/' \
    "$dir/summary.json" | tr -d , | awk '{ D = 0; for (i = 2; i <= 11; i++) D += $i
    printf "roof %.7f m, dampers %.6e J, Newton %.3f/%d, failures %d, residual/input %.2e, cpu %.3f s\n",
           $1, D, $14, $15, $16, $13 / $12, $17 }'
