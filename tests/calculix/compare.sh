#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# One deck through the stock and the patched ccx (build.sh), one thread each, and their
# outputs compared. The patched run gets LAWS as its laws file (JOB.fricreg: each surface
# interaction's law, README.md); then the same iterations (the .sta files, equal line for line)
# and every number of the .dat and .frd files within TOL of its range (compare.awk). With LAWS
# "-" the patched run has no laws file, so ccx's own code runs everywhere: its .dat and .sta
# must equal stock's byte for byte, and its .frd too but for the date and time it records.
# The runs stay in RUN_DIR/stock and RUN_DIR/patched.
# With FRICREG_CCX_COUNTER (count_calls.c's module) the patched run counts its calls to fricreg.
# Usage: compare.sh CCX_DIR DECK RUN_DIR LAWS [TOL]   (DECK: a .inp or .inp.gz file)
ccx_dir=$1 deck=$2 run=$3 laws=$4 tol=${5:-1e-6}
here=$(cd "$(dirname "$0")" && pwd)
job=$(basename "$deck" .gz)
job=${job%.inp}
. "$(dirname "$0")/one_thread.sh"
fails=0
for build in stock patched; do
    dir=$run/$build
    rm -rf "$dir" && mkdir -p "$dir" || exit 1
    zcat -f "$deck" >"$dir/$job.inp" || exit 1
    if [ $build = patched ] && [ "$laws" != - ]; then
        cp "$laws" "$dir/$job.fricreg" || exit 1
    fi
    start=$(date +%s.%N)
    if [ $build = patched ] && [ -n "$FRICREG_CCX_COUNTER" ]; then
        (cd "$dir" && FRICREG_CCX_COUNTS=$dir/counts LD_PRELOAD=$FRICREG_CCX_COUNTER \
            "$ccx_dir/$build/ccx" -i "$job" >"$job.log" 2>&1)
    else
        (cd "$dir" && "$ccx_dir/$build/ccx" -i "$job" >"$job.log" 2>&1)
    fi
    status=$?
    echo "$job $build $status $start $(date +%s.%N)" | awk '{printf "%s: %s ccx: exit %d, %.1f s\n", $1, $2, $3, $5 - $4}'
    if [ $status -ne 0 ] || grep -q '^ \*ERROR' "$dir/$job.log"; then
        echo "FAIL: $job: $build ccx failed"; tail -n 5 "$dir/$job.log"; fails=$((fails + 1))
    fi
done
[ $fails -eq 0 ] || { echo "0 passed, 1 failed"; exit 1; }
# count_calls.c's line: how often the patched ccx called the kernel, and how often it slid
if [ -n "$FRICREG_CCX_COUNTER" ] && [ ! -s "$run/patched/counts" ]; then
    echo "$job: fricreg_element_eval never called (no friction contact reached)"
fi
[ -s "$run/patched/counts" ] &&
    awk -v job="$job" '{printf "%s: fricreg_element_eval called %d times, sliding in %d, on the stick/slip border in %d\n", job, $2, $4, $6}' "$run/patched/counts"

s=$run/stock/$job p=$run/patched/$job
if [ "$laws" = - ]; then # ccx's own code in both: the same bytes
    undated() { grep -v '^    1U\(DATE\|TIME\) ' "$1" | cksum; }
    for ext in sta dat frd; do
        [ -e "$s.$ext" ] || [ -e "$p.$ext" ] || continue
        if [ "$(undated "$s.$ext")" = "$(undated "$p.$ext")" ]; then
            echo "$job: no laws file: the .$ext file is stock's"
        else
            echo "FAIL: $job: no laws file, yet the .$ext file differs from stock's"
            fails=$((fails + 1))
        fi
    done
    if [ -s "$run/patched/counts" ]; then
        echo "FAIL: $job: fricreg called without a laws file"
        fails=$((fails + 1))
    fi
    [ $fails -eq 0 ] && echo "1 passed, 0 failed" || echo "0 passed, 1 failed"
    exit $fails
fi
# the iterations: every increment's attempts and iterations, line for line
if cmp -s "$s.sta" "$p.sta"; then
    echo "$job: the same increments and iterations ($(grep -c '^ *[0-9]' "$s.sta") increments)"
else
    echo "FAIL: $job: the .sta files differ (increments, attempts or iterations)"
    diff "$s.sta" "$p.sta" | head -n 10
    fails=$((fails + 1))
fi
for ext in dat frd; do
    [ -s "$s.$ext" ] || [ -s "$p.$ext" ] || continue
    out=$(awk -v tol="$tol" -v name="$job.$ext" -f "$here/compare.awk" "$s.$ext" "$p.$ext")
    status=$?
    printf '%s\n' "$out" | grep -v ' passed, '
    [ $status -eq 0 ] || fails=$((fails + 1))
done
[ $fails -eq 0 ] && echo "1 passed, 0 failed" || echo "0 passed, 1 failed"
[ $fails -eq 0 ]
