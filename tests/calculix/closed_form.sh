#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# Test calculix_closed_form: the closed-form deck (decks/iwanclosed.inp, its laws file
# decks/iwanclosed.fricreg) through the patched ccx, node to surface and surface to surface
# (the deck's TYPE changed), at the deck's increment and at half of it, one thread. Each block's
# loop dissipations, the drive's work round each closed loop (its total reaction RF_x against the
# prescribed x, trapezoids over the increments), against the closed forms per unit area
# (area 1, pressure p = 100, mu = 0.2, k_t = 1e5):
#   L, jenkins_3d:  4 mu p (A - mu p / k_t)                        where positive, else 0
#   R, iwan_3d 5:   sum_s 4 phi_s (A - phi_s / k_s) over the sliders with A > phi_s / k_s,
#                   k_s = k_t / 5, phi_s = c_s mu p, c_s = 2 s / 30
# at A = 1e-4, 2.5e-4, 5e-4; each within TOL of the loop's scale 4 mu p A (the dissipation of
# rigid-plastic Coulomb), and at the half increment no farther than at the whole one (the
# trapezoids converge). The runs stay in RUN_DIR.
# Usage: closed_form.sh CCX_DIR DECK LAWS RUN_DIR [TOL]
ccx_dir=$1 deck=$2 laws=$3 run=$4 tol=${5:-1e-3}
job=$(basename "$deck" .inp)
. "$(dirname "$0")/one_thread.sh"
fail() { echo "FAIL: $*"; echo "0 passed, 1 failed"; exit 1; }
grep -qx '0.2, 1.e5' "$deck" || fail "$deck's *FRICTION is not mu = 0.2, k_t = 1e5 (closed_form.sh)"
grep -qx '0.05, 15., 1.e-5, 0.05' "$deck" || fail "$deck's loop step is not 0.05 of 15 (closed_form.sh)"
fails=0
for type in NODE SURFACE; do
    for inc in 0.05 0.025; do
        dir=$run/$type-$inc
        rm -rf "$dir" && mkdir -p "$dir" && cp "$laws" "$dir/$job.fricreg" || exit 1
        sed -e "s/TYPE=NODE TO SURFACE/TYPE=$type TO SURFACE/" \
            -e "s/^0.05, 15., 1.e-5, 0.05\$/$inc, 15., 1.e-5, $inc/" "$deck" >"$dir/$job.inp" ||
            exit 1
        (cd "$dir" && "$ccx_dir/patched/ccx" -i "$job" >"$job.log" 2>&1)
        if [ $? -ne 0 ] || grep -q '^ \*ERROR' "$dir/$job.log"; then
            tail -n 5 "$dir/$job.log"
            fail "$job, $type to surface, increment $inc: the patched ccx failed"
        fi
        # the loops' works: the .dat's "total force ... for set NL|NR and time T" blocks,
        # step 2's time tau = T - 1, the drive U(tau) from the deck's amplitude Aloops
        awk -v type=$type -v inc=$inc '
        function drive(tau,   k) {
            for (k = 1; k < n; k++)
                if (tau <= at[k + 1]) return val[k] + (val[k + 1] - val[k]) * (tau - at[k]) / (at[k + 1] - at[k])
            return val[n]
        }
        BEGIN { n = split("0 1 3 5 6 8 10 11 13 15", at, " ")
                split("0 1e-4 -1e-4 1e-4 2.5e-4 -2.5e-4 2.5e-4 5e-4 -5e-4 5e-4", val, " ")
                split("1 5 6 10 11 15", win, " ") }
        /total force \(fx,fy,fz\) for set N[LR] and time/ { set = $6; tau = $NF - 1; getline; getline
            u = drive(tau)
            for (w = 1; w <= 3; w++)
                if (tau > win[2 * w - 1] + 1e-9 && tau <= win[2 * w] + 1e-9)
                    work[set, w] += 0.5 * ($1 + last[set]) * (u - lastu[set])
            last[set] = $1; lastu[set] = u }
        END { for (w = 1; w <= 3; w++) printf "%s %s %d %.10e %.10e\n", type, inc, w, work["NL", w], work["NR", w] }
        ' "$dir/$job.dat" >"$dir/works.txt" || exit 1
        [ "$(wc -l <"$dir/works.txt")" -eq 3 ] || fail "$dir/$job.dat: no loops found"
        cat "$dir/works.txt" >>"$run/works.txt"
    done
done
awk -v tol="$tol" '
function iwan(A,   s, phi, k, sum) {
    for (s = 1; s <= 5; s++) { phi = 20 * 2 * s / 30; k = 2e4; if (A > phi / k) sum += 4 * phi * (A - phi / k) }
    return sum
}
BEGIN { amp[1] = 1e-4; amp[2] = 2.5e-4; amp[3] = 5e-4 }
{ A = amp[$3]; scale = 4 * 20 * A
  jk = A > 20 / 1e5 ? 4 * 20 * (A - 20 / 1e5) : 0
  eL = ($4 - jk) / scale; eR = ($5 - iwan(A)) / scale
  printf "%s to surface, increment %s, A = %.2e: L (jenkins_3d) %.6e against %.6e (%+.1e of 4 mu p A); R (iwan_3d 5) %.6e against %.6e (%+.1e)\n", $1, $2, A, $4, jk, eL, $5, iwan(A), eR
  for (b = 0; b < 2; b++) {
      e = b == 0 ? eL : eR; e = e < 0 ? -e : e
      if (e > tol) { print "FAIL: beyond " tol; bad = 1 }
      key = $1 SUBSEP $3 SUBSEP b
      if ($2 == "0.05") whole[key] = e
      else if (e > whole[key] + 1e-7) { print "FAIL: the half increment is farther from the closed form"; bad = 1 }
  } }
END { exit bad }' "$run/works.txt" || fails=1
[ $fails -eq 0 ] && echo "1 passed, 0 failed" || echo "0 passed, 1 failed"
exit $fails
