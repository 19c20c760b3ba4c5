#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# Test calculix_iwan: the Iwan deck (decks/iwanloop.inp) through the patched-iwan ccx
# (build.sh: fricreg's iwan_3d with frccxi.f's 5 sliders in ccx's penalty contact), one
# thread; its printed contact history (*CONTACT PRINT, 17 digits) into RUN_DIR/history.txt
# ("node increment gap t1 t2 p tau1 tau2"), the kernel driven alone on it (iwan_alone.c: the
# dissipations and stresses to 1e-6), and the hysteresis loops plotted by gnuplot into
# RUN_DIR/iwan_loop.svg (with gnuplot absent: a note, not a failure; the numbers are the test).
# Usage: iwan.sh CCX_DIR DECK RUN_DIR IWAN_ALONE [TOL]
ccx_dir=$1 deck=$2 run=$3 alone=$4 tol=${5:-1e-6}
# the deck's *FRICTION (mu, stick slope) and frccxi.f's sliders
mu=0.2 kt=1.e5 ns=5
job=$(basename "$deck" .inp)
export OMP_NUM_THREADS=1 NUMBER_OF_PROCESSORS=1 CCX_NPROC_STIFFNESS=1 CCX_NPROC_RESULTS=1 \
       CCX_NPROC_EQUATION_SOLVER=1 CCX_NPROC_CFD=1 CCX_NPROC_BIOTSAVART=1 CCX_NPROC_SENS=1
fail() { echo "FAIL: $*"; echo "0 passed, 1 failed"; exit 1; }
grep -qx '0.2, 1.e5' "$deck" || fail "$deck's *FRICTION is not mu = $mu, k_t = $kt (iwan.sh)"
grep -q "PARAMETER (NS = $ns)" "$(dirname "$0")/frccxi.f" || fail "frccxi.f's NS is not $ns (iwan.sh)"
rm -rf "$run" && mkdir -p "$run" && cp "$deck" "$run/$job.inp" || exit 1
start=$(date +%s.%N)
(cd "$run" && "$ccx_dir/patched-iwan/ccx" -i "$job" >"$job.log" 2>&1)
status=$?
echo "$job $status $start $(date +%s.%N) $(grep -c '^ *[0-9]' "$run/$job.sta" 2>/dev/null)" |
    awk '{printf "%s: patched-iwan ccx: exit %d, %.1f s, %d increments\n", $1, $2, $4 - $3, $5}'
if [ $status -ne 0 ] || grep -q '^ \*ERROR' "$run/$job.log"; then
    tail -n 5 "$run/$job.log"; fail "$job: the patched-iwan ccx failed"
fi
# The .dat's contact blocks: CDISP (gap, t1, t2) then CSTRESS (p, tau1, tau2) per node at each
# increment; a line printed with ccx's 7 digits (not the patch's 17) is refused.
awk '
/relative contact displacement \(slave node/ { mode = "d"; ++inc; next }
/contact stress \(slave node/ { mode = "s"; next }
/^ *[a-z]/ { mode = ""; next }
mode != "" && NF == 4 && $1 ~ /^[0-9]+$/ {
    for (i = 2; i <= 4; ++i) if (length($i) < 20) { print "short " $i; exit 1 }
    if (mode == "d") d[inc, $1] = $2 " " $3 " " $4
    else { if (!((inc, $1) in d)) { print "stress before displacement"; exit 1 }
           print $1, inc, d[inc, $1], $2, $3, $4 }
}' "$run/$job.dat" >"$run/history.txt" || fail "$job.dat: $(tail -n 1 "$run/history.txt") (not 17 digits?)"
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
