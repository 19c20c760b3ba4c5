#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""The frequency response of a two-dof structure with a contact that closes a gap, by harmonic
balance, with each point's Floquet stability and the bifurcations located on the branch.

The gap pair of tests/floquet/test_hb_stability.c: M = I, K = [[140, -20], [-20, 180]] N/m,
C = 0.002 K, a contact element (jenkins_normal: kt = 40 N/m, mu = 0.01, kn = 500 N/m) whose
normal displacement is -x_1 and which closes at x_1 = -0.02 m (n0 = -10 N: a gap n0/kn), forced
by (2, 1) cos Ωt N. The hardening contact bends the resonance over: two turning points (TP),
and between them a stretch that loses stability at two Neimark-Sacker bifurcations (NS).

Writes frf_stability.csv (Ω, the RMS of each dof, stable, the largest |multiplier|) always and
frf_stability.png (stable points solid, unstable dashed, bifurcations marked) where matplotlib
is installed. Run: PYTHONPATH=build/python python3 frf_stability.py
"""
import numpy as np

import fricreg

K = np.array([[140.0, -20.0], [-20.0, 180.0]])
J = np.array([[0.0, 1.0],    # the tangential row: dof 2
              [-1.0, 0.0]])  # the normal row: g = -x_1, pressing when x_1 < 0
contact = fricreg.Element("jenkins_normal", [40.0, 0.01, 500.0, -10.0, 0.0])
hb = fricreg.HarmonicBalance(np.eye(2), K, 0.002 * K, harmonics=15,
                             elements=[(contact, J)], excitation=([2.0, 1.0], None))
hb.set_stability(True)
frf = hb.frequency_response(11.0, 17.0)

kinds = [b.kind for b in frf.bifurcations]
print("%d points, %d unstable; bifurcations: %s" % (len(frf.omega), np.sum(~frf.stable),
                                                   ", ".join("%s at %.5f rad/s" % (b.kind, b.omega)
                                                             for b in frf.bifurcations)))
# as tests/floquet/test_hb_stability.c finds
assert kinds.count("TP") == 2 and kinds.count("NS") == 2

np.savetxt("frf_stability.csv",
           np.column_stack([frf.omega, frf.rms, frf.stable, frf.mu_max]), delimiter=",",
           header="omega,rms_1,rms_2,stable,mu_max", comments="")
try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    print("matplotlib not installed: frf_stability.csv only")
else:
    fig, ax = plt.subplots(figsize=(6, 4))
    # one line per run of equal stability, each run joined to the next point
    edges = np.flatnonzero(np.diff(frf.stable.astype(int))) + 1
    for run in np.split(np.arange(len(frf.omega)), edges):
        stop = min(run[-1] + 2, len(frf.omega))
        stable = frf.stable[run[0]]
        ax.plot(frf.omega[run[0]:stop], frf.rms[run[0]:stop, 0], "-" if stable else "--",
                color="C0" if stable else "C3", label=None)
    for b in frf.bifurcations:
        ax.plot(b.omega, b.rms[0], "o" if b.kind == "TP" else "s", color="k")
        ax.annotate(b.kind, (b.omega, b.rms[0]), textcoords="offset points", xytext=(5, 5))
    ax.plot([], [], "-", color="C0", label="stable")
    ax.plot([], [], "--", color="C3", label="unstable")
    ax.set_xlabel("excitation frequency (rad/s)")
    ax.set_ylabel("RMS of dof 1 (m)")
    ax.set_title("Gap pair, H = 15: Floquet stability and bifurcations")
    ax.legend()
    fig.tight_layout()
    fig.savefig("frf_stability.png", dpi=100)
    print("wrote frf_stability.csv and frf_stability.png")
