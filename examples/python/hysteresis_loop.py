#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Hysteresis loops of a bolted lap joint's Iwan element (Segalman's four-parameter model) at
three amplitudes, and the dissipation per cycle against its closed form.

Each slider, a spring k_s in series with a Coulomb slider of bound phi_s, that slips under
u = A sin t dissipates 4 phi_s (A - phi_s/k_s) a cycle; a stuck one dissipates nothing. The
three amplitudes are evaluated as three points of one Element call per time step.

Writes hysteresis_loop.csv (t, then u and f at each amplitude) always, and hysteresis_loop.png
where matplotlib is installed. Run: PYTHONPATH=build/python python3 hysteresis_loop.py
"""
import numpy as np

import fricreg

NS = 20
params = fricreg.segalman(NS, 1.0, 10.0, -0.5, 0.1, 0.01)  # fs = 1 N, kt = 10 N/m
iwan = fricreg.Element("iwan", params)
k, phi = params[:NS], params[NS:]
amplitudes = np.array([0.01, 0.05, 0.2])  # m: microslip, partial slip, macroslip

steps = 2000
t = 2 * np.pi * np.arange(1, steps + steps // 4 + 1) / steps
state = iwan.init(len(amplitudes))
u_hist, f_hist = [], []
dissipated = np.zeros(len(amplitudes))
for s, ts in enumerate(t, start=1):
    u = amplitudes[:, None] * np.sin(ts)
    r = iwan.eval(u, state, tangent=False)
    slider_forces = k * (u - r.state)  # each slider's force after the step
    dissipated += np.sum(slider_forces * (r.state - state), axis=1)
    state = r.state
    if s == steps // 4:  # count one whole cycle from the first turn
        dissipated[:] = 0.0
    u_hist.append(u[:, 0])
    f_hist.append(r.f[:, 0])

slipping = amplitudes[:, None] > phi / k
exact = np.sum(np.where(slipping, 4 * phi * (amplitudes[:, None] - phi / k), 0.0), axis=1)
for a, d, e in zip(amplitudes, dissipated, exact):
    print("A = %-5g m: dissipation per cycle %.12f J, closed form %.12f J" % (a, d, e))
assert np.allclose(dissipated, exact, rtol=1e-12)

u_hist, f_hist = np.array(u_hist), np.array(f_hist)
header = "t," + ",".join("u_%g,f_%g" % (a, a) for a in amplitudes)
columns = [t] + [c for i in range(len(amplitudes)) for c in (u_hist[:, i], f_hist[:, i])]
np.savetxt("hysteresis_loop.csv", np.column_stack(columns), delimiter=",", header=header,
           comments="")
try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    print("matplotlib not installed: hysteresis_loop.csv only")
else:
    fig, ax = plt.subplots(figsize=(5, 4))
    last = slice(steps // 4, None)
    for i, a in enumerate(amplitudes):
        ax.plot(u_hist[last, i] / a, f_hist[last, i], label="A = %g m" % a)
    ax.set_xlabel("u / A")
    ax.set_ylabel("f (N)")
    ax.set_title("Iwan element, %d sliders (Segalman)" % NS)
    ax.legend()
    fig.tight_layout()
    fig.savefig("hysteresis_loop.png", dpi=100)
    print("wrote hysteresis_loop.csv and hysteresis_loop.png")
