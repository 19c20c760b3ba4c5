#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# Test calculix_iwan: the Iwan deck (decks/iwanloop.inp) through the patched ccx with its laws
# file (decks/iwanloop.fricreg: fricreg's iwan_3d, 5 sliders, in ccx's penalty contact), one
# thread; its printed contact history (*CONTACT PRINT, ccx's 7 digits) into
# RUN_DIR/history.txt ("node increment gap t1 t2 p tau1 tau2"), the kernel driven alone on it
# (iwan_alone.c: the dissipations and stresses to 1e-6), and the hysteresis loops plotted by
# gnuplot into RUN_DIR/iwan_loop.svg (with gnuplot absent: a note, not a failure; the numbers
# are the test).
# Usage: iwan.sh CCX_DIR DECK LAWS RUN_DIR IWAN_ALONE [TOL]
ccx_dir=$1 deck=$2 laws=$3 run=$4 alone=$5 tol=${6:-1e-6}
# the deck's *FRICTION (mu, stick slope) and the laws file's sliders
mu=0.2 kt=1.e5 ns=5
job=$(basename "$deck" .inp)
. "$(dirname "$0")/one_thread.sh"
fail() { echo "FAIL: $*"; echo "0 passed, 1 failed"; exit 1; }
grep -qx '0.2, 1.e5' "$deck" || fail "$deck's *FRICTION is not mu = $mu, k_t = $kt (iwan.sh)"
grep -qx "\\*  *iwan_3d  *$ns" "$laws" || fail "$laws is not every interaction on iwan_3d $ns (iwan.sh)"
rm -rf "$run" && mkdir -p "$run" && cp "$deck" "$run/$job.inp" && cp "$laws" "$run/$job.fricreg" ||
    exit 1
start=$(date +%s.%N)
(cd "$run" && "$ccx_dir/patched/ccx" -i "$job" >"$job.log" 2>&1)
status=$?
echo "$job $status $start $(date +%s.%N) $(grep -c '^ *[0-9]' "$run/$job.sta" 2>/dev/null)" |
    awk '{printf "%s: patched ccx: exit %d, %.1f s, %d increments\n", $1, $2, $4 - $3, $5}'
if [ $status -ne 0 ] || grep -q '^ \*ERROR' "$run/$job.log"; then
    tail -n 5 "$run/$job.log"; fail "$job: the patched ccx failed"
fi
# The .dat's contact blocks: CDISP (gap, t1, t2) then CSTRESS (p, tau1, tau2) per node at each
# increment.
awk '
/relative contact displacement \(slave node/ { mode = "d"; ++inc; next }
/contact stress \(slave node/ { mode = "s"; next }
/^ *[a-z]/ { mode = ""; next }
mode != "" && NF == 4 && $1 ~ /^[0-9]+$/ {
    if (mode == "d") d[inc, $1] = $2 " " $3 " " $4
    else { if (!((inc, $1) in d)) { print "stress before displacement"; exit 1 }
           print $1, inc, d[inc, $1], $2, $3, $4 }
}' "$run/$job.dat" >"$run/history.txt" || fail "$job.dat: $(tail -n 1 "$run/history.txt")"
[ -s "$run/history.txt" ] || fail "$job.dat has no contact history"
"$alone" "$run/history.txt" $kt $mu $ns "$tol" "$run/loop.txt" >"$run/alone.txt"
status=$?
cat "$run/alone.txt"
# the figure's subtitle: the total dissipations (per unit area) and their difference
sums=$(awk '/^all .* nodes: dissipation ccx/ {printf "dissipation per unit area, all nodes: ccx %s, kernel alone %s (relative difference %s)", $6, $9, $12}' "$run/alone.txt" | tr -d ',')
if command -v gnuplot >/dev/null; then
    nodes=$(awk '{print $1}' "$run/history.txt" | sort -nu | tr '\n' ' ')
    gnuplot <<GP || fail "gnuplot"
set terminal svg size 900,600 dynamic noenhanced
set output '$run/iwan_loop.svg'
set title "fricreg's Iwan law (iwan_3d, $ns sliders) in CalculiX: the contact nodes' hysteresis loops\n$sums"
set xlabel "t1, the relative tangential displacement along the drag (x)"
set ylabel "tau1, the shear stress along x"
set key left top
set grid
nodes = "$nodes"
plot for [i=0:words(nodes)-1] '$run/loop.txt' index i using 1:2 with lines lw 2 title 'ccx, node '.word(nodes, i+1), \
     for [i=0:words(nodes)-1] '$run/loop.txt' index i using 1:3 with points pt 6 ps 0.6 title 'kernel alone, node '.word(nodes, i+1)
GP
    [ -s "$run/iwan_loop.svg" ] && echo "$job: the loops plotted in $run/iwan_loop.svg"
else
    echo "$job: no gnuplot, no figure (the loops are in $run/loop.txt)"
fi
exit $status
