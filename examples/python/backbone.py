#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""The first nonlinear mode of NLvib's 3-dof chain with two Jenkins elements: its natural
frequency ω(a) and damping ratio ζ(a) against the modal amplitude, by harmonic balance and
the extended periodic motion concept (Krack 2015), continued through the folds of an internal
resonance.

The chain (bench/nlvib/chain_jenkins.m): unit masses and springs ground-1-2-3, dampers
0.02 K, Jenkins elements kt = 20 N/m, mu N = 1 N at dof 1 and between dofs 1 and 2. The stuck
chain's first mode moves mostly dof 3, so the elements hardly load: up to a = 1 the backbone is
that linear mode (modal damping: ω = 1.3749 rad/s, ζ its own). Where the elements start to slip
its shape leaves the stuck mode, and the backbone folds where harmonics of ω meet the stuck
chain's higher modes (the crossings printed: internal resonances), while ζ rises with the
friction's dissipation.

Writes backbone.csv (a, ω, ζ) always and backbone.png where matplotlib is installed.
Run: PYTHONPATH=build/python python3 backbone.py
"""
import numpy as np

import fricreg

K = np.array([[2.0, -1.0, 0.0], [-1.0, 2.0, -1.0], [0.0, -1.0, 2.0]])
J = np.array([[1.0, 0.0, 0.0], [-1.0, 1.0, 0.0]])
hb = fricreg.HarmonicBalance(np.eye(3), K, 0.02 * K, harmonics=7,
                             elements=[(fricreg.Element("jenkins", [20.0, 1.0]), J)])
mode = hb.backbone(0, 0.01, 3.0, npoints=120, damping="modal", through_folds=True)

stuck = np.sqrt(np.linalg.eigvalsh(K + 20.0 * J.T @ J)[0])
print("stuck linear mode %.6f rad/s, backbone starts at %.6f" % (stuck, mode.omega[0]))
assert abs(mode.omega[0] - stuck) <= 1e-9 * stuck
folds = [p for p in mode.special_points if p.kind == "fold"]
for p in mode.special_points:  # in the branch's order
    if p.kind == "fold":
        print("fold at a = %.5f: omega = %.5f, zeta = %.5f" % (p.amplitude, p.omega, p.zeta))
    else:
        print("%d omega meets mode %d at a = %.5f (omega = %.5f)"
              % (p.harmonic, p.mode, p.amplitude, p.omega))

np.savetxt("backbone.csv", np.column_stack([mode.amplitude, mode.omega, mode.zeta]),
           delimiter=",", header="amplitude,omega,zeta", comments="")
try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    print("matplotlib not installed: backbone.csv only")
else:
    fig, (top, bottom) = plt.subplots(2, 1, sharex=True, figsize=(6, 5))
    top.semilogx(mode.amplitude, mode.omega)
    bottom.semilogx(mode.amplitude, mode.zeta)
    for fold in folds:
        top.plot(fold.amplitude, fold.omega, "ko")
        bottom.plot(fold.amplitude, fold.zeta, "ko")
    top.set_ylabel("natural frequency (rad/s)")
    bottom.set_ylabel("damping ratio")
    bottom.set_xlabel("modal amplitude")
    top.set_title("NLvib's chain, first mode (folds marked)")
    fig.tight_layout()
    fig.savefig("backbone.png", dpi=100)
    print("wrote backbone.csv and backbone.png")
