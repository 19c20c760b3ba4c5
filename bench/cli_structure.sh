#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# bench/cli_structure.sh — `fricreg-sim structure` at n degrees of freedom (default 10^6): the
# shear chain of structure_scaling.c written as its files (fricreg-bench-structure-files), the
# Matrix Market reader timed alone on each (fricreg-bench-mtx-read: seconds, peak resident
# memory), then the command itself, Newmark at dt = 5 ms for 10 and for 110 steps under
# /usr/bin/time: CPU seconds per step from the difference (the first steps factor K_eff), the
# peak resident memory of the whole run. Not run by ctest (about a minute at 10^6, and 0.1 GB
# of files in DIR).
#   usage: bench/cli_structure.sh BUILD_DIR [N [K [DIR]]]   (BUILD_DIR built with
#          -DFRICREG_BENCH=ON, as bench/run.sh builds build-bench)
set -eu
build=$1 n=${2:-1000000} k=${3:-10}
dir=${4:-${TMPDIR:-/tmp}/fricreg-cli-structure.$n}
[ -x /usr/bin/time ] || { echo "cli_structure.sh: needs /usr/bin/time (Debian: time)" >&2; exit 1; }
mkdir -p "$dir"
"$build/bench/fricreg-bench-structure-files" "$n" "$k" "$dir"
echo "n = $n, k = $k dampers, files in $dir: $(du -sh "$dir" | cut -f1)"
echo "machine: $(nproc) CPUs, load average $(cut -d' ' -f1-3 /proc/loadavg)"
echo
echo "the reader alone: file rows cols entries wall_s cpu_s peak_before_MiB peak_MiB"
for f in M K J; do
    "$build/bench/fricreg-bench-mtx-read" "$dir/$f.mtx"
done
echo

# One run of STEPS steps: its summary's cpu_seconds (the run, from the first step), the
# process's CPU seconds and peak resident memory (MiB).
run() {
    /usr/bin/time -f '%U %S %M' -o "$dir/time.txt" "$build/fricreg-sim" structure \
        --mass "$dir/M.mtx" --stiffness "$dir/K.mtx" --rayleigh "$(cat "$dir/rayleigh.txt")" \
        --contacts "$dir/J.mtx" --mun "$dir/mun.txt" --ground-accel "$dir/ground.txt" \
        --eps 1e-3 --integrator newmark --dt 0.005 --t-end "$(echo "$1" | awk '{ print $1 * 0.005 }')" \
        >"$dir/summary.json"
    run_cpu=$(sed -n 's/.*"cpu_seconds": \([0-9.]*\)[,}].*/\1/p' "$dir/summary.json")
    read -r user sys kib <"$dir/time.txt"
    echo "$1 $run_cpu $(echo "$user $sys $kib" | awk '{ printf "%.2f %.1f", $1 + $2, $3 / 1024 }')"
}
echo "fricreg-sim structure, Newmark: steps run_cpu_s process_cpu_s peak_MiB"
short=$(run 10)
long=$(run 110)
echo "$short"
echo "$long"
echo "$short $long" | awk '{ printf "per step: %.1f ms of CPU (110 - 10 steps); set-up and the first 10 steps: %.2f s; peak %.0f MiB\n", ($6 - $2) / 100 * 1000, $2, $8 }'
