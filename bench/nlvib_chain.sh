#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# nlvib_chain.sh — fricreg's harmonic balance against NLvib (M. Krack and J. Gross,
# https://github.com/maltekrack/NLvib, not part of fricreg) on the 3-dof chain with two Jenkins
# elements (bench/nlvib/chain_jenkins.m says which), H = 7 (or $H), Omega 0.5 to 2: both
# frequency responses with their defaults (NLvib: example 07's step), each dof's RMS at NLvib's
# points against a fine fricreg branch (ds = ds_max = 0.002), and the peaks. Prints the
# figures; needs Octave (Debian's octave) and an NLvib checkout.
#
#   bench/nlvib_chain.sh NLVIB_DIR [FRICREG_SIM]
set -eu
nlvib=$(cd "${1:?usage: nlvib_chain.sh NLVIB_DIR [FRICREG_SIM]}" && pwd)
sim=${2:-fricreg-sim}
H=${H:-7}
here=$(cd "$(dirname "$0")" && pwd)
d=$(mktemp -d)
trap 'rm -rf "$d"' EXIT
printf '%%%%MatrixMarket matrix coordinate real symmetric\n3 3 3\n1 1 1\n2 2 1\n3 3 1\n' >"$d/M.mtx"
printf '%%%%MatrixMarket matrix coordinate real symmetric\n3 3 5\n1 1 2\n2 1 -1\n2 2 2\n3 2 -1\n3 3 2\n' >"$d/K.mtx"
printf '%%%%MatrixMarket matrix coordinate real symmetric\n3 3 5\n1 1 0.04\n2 1 -0.02\n2 2 0.04\n3 2 -0.02\n3 3 0.04\n' >"$d/C.mtx"
printf '%%%%MatrixMarket matrix coordinate real general\n2 3 3\n1 1 1\n2 1 -1\n2 2 1\n' >"$d/J.mtx"
printf '20 1\n20 1\n' >"$d/P.txt"
printf '0 0\n1 0\n0 0\n' >"$d/F.txt"
model="--mass $d/M.mtx --stiffness $d/K.mtx --damping $d/C.mtx --jenkins $d/J.mtx
       --jenkins-params $d/P.txt --excitation $d/F.txt --harmonics $H --omega-start 0.5
       --omega-end 2"
# shellcheck disable=SC2086
"$sim" hb $model >"$d/fricreg.json"
# shellcheck disable=SC2086
"$sim" hb $model --ds 0.002 --ds-max 0.002 --max-points 100000 --output frf >"$d/fricreg.csv"
cd "$here/nlvib"
octave --no-gui --quiet --eval "nlvib = '$nlvib'; H = $H; out = '$d/nlvib.csv'; chain_jenkins"
octave --no-gui --quiet --eval "
  s = jsondecode(fileread('$d/fricreg.json'));
  printf('fricreg H = %d: %d points, %.2f s (Hill stability on)\n', $H, s.points, s.cpu_seconds);
  peaks = [[s.dofs.peak_omega]' [s.dofs.peak_rms]'];
  ref = '$d/nlvib.csv'; fr = '$d/fricreg.csv'; compare_frf"
