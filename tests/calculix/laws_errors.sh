#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# Test calculix_laws_errors: the patched ccx refuses a laws file it cannot follow, and a deck
# whose state cannot hold its sliders: it stops with a message that says why (frccx.c). The
# closed-form deck (DECK, interactions SIL and SIR) with
#   a law that is not jenkins_3d or iwan_3d, an interaction the deck does not define,
#   iwan_3d with numbers c_s that do not sum to 1, and *DEPVAR 9 under iwan_3d 5.
# Usage: laws_errors.sh CCX_DIR DECK RUN_DIR
ccx_dir=$1 deck=$2 run=$3
job=$(basename "$deck" .inp)
. "$(dirname "$0")/one_thread.sh"
fails=0
# case: laws file | sed on the deck | the message's words
refused() {
    dir=$run/$1
    rm -rf "$dir" && mkdir -p "$dir" || exit 1
    printf '%s\n' "$2" >"$dir/$job.fricreg"
    sed -e "$3" "$deck" >"$dir/$job.inp" || exit 1
    (cd "$dir" && "$ccx_dir/patched/ccx" -i "$job" >"$job.log" 2>&1)
    status=$?
    if [ $status -ne 0 ] && grep -q -- "$4" "$dir/$job.log"; then
        echo "$1: refused (exit $status): $(grep -- "$4" "$dir/$job.log" | head -n 1)"
    else
        echo "FAIL: $1: exit $status, no '$4' in $dir/$job.log"
        fails=$((fails + 1))
    fi
}
refused unknown-law 'SIR  iwan' 's/^//' "'iwan' is not jenkins_3d or iwan_3d"
refused unknown-interaction 'SIX  jenkins_3d' 's/^//' 'no \*SURFACE INTERACTION is named SIX'
refused sum-not-one 'SIR  iwan_3d  2  0.5  0.6' 's/^//' 'summing to 1'
refused depvar-too-small 'SIR  iwan_3d  5' '/^\*DEPVAR$/{n;s/24/9/}' '\*DEPVAR 24 in the deck (has 9)'
[ $fails -eq 0 ] && echo "1 passed, 0 failed" || echo "0 passed, 1 failed"
exit $fails
