# SPDX-License-Identifier: GPL-3.0-or-later
"""The paper's Fig. 9 from Python: the chain of Quinn (2004), Sec. 3.2, integrated by RK4 in
numpy with fricreg.law_eval as its friction, gives fricreg-sim chain's dissipation per cycle
bit for bit, and the paper's D = 0.0105."""
import json
import math
import subprocess

import numpy as np

import fricreg
from conftest import fricreg_sim

N, A, OMEGA = 32, 0.25, 0.5   # the paper's chain (spec: reference system 2)
DT = 0.01
EPS = 10 * OMEGA * DT         # eps = 10 omega dt (Sec. 3.2)


def rhs(t, y):
    """u' = v, v' = a_free + f, D' = -(1/n) v . f (src/sim/systems/chain.c's scaling)."""
    u, v = y[:N], y[N:2 * N]
    a_free = np.empty(N)
    # math.sin is libm's, as chain.c's; numpy's sin may use its own SIMD code (AVX-512), ulps apart
    a_free[0] = -N * N * (u[0] - u[1]) + N * A * math.sin(OMEGA * t)
    a_free[1:-1] = -N * N * (-u[:-2] + 2 * u[1:-1] - u[2:])
    a_free[-1] = -N * N * (-u[-2] + 2 * u[-1])
    f = fricreg.law_eval("quinn", v, -a_free, 1.0, EPS)  # W = I: f_eq = -a_free
    return np.concatenate([v, a_free + f, [-power(v, f) / N]])


def power(v, f):
    """v . f summed as chain.c sums it (not as a BLAS dot might): 8 partial sums, block after
    block, then added in order."""
    lanes = np.zeros(8)
    for block in (v * f).reshape(-1, 8):
        lanes = lanes + block
    total = 0.0
    for lane in lanes:
        total += lane
    return total


def rk4(t, y, h):
    """One classical RK4 step, its sum in src/ode/rk4_classic.c's order."""
    k1 = rhs(t, y)
    k2 = rhs(t + h / 2, y + h / 2 * k1)
    k3 = rhs(t + h / 2, y + h / 2 * k2)
    k4 = rhs(t + h, y + h * k3)
    return y + h / 6 * (((k1 + 2 * k2) + 2 * k3) + k4)


def dissipation_per_cycle(cycles):
    """fricreg-sim's fixed-step rk4: each step of 2 dt two classical steps of dt, the last step
    of a cycle shortened to end on it (src/sim/integrate.c)."""
    period, step = 2 * np.pi / OMEGA, 2 * DT
    y, t, D = np.zeros(2 * N + 1), 0.0, []
    for cycle in range(1, cycles + 1):
        end, start = cycle * period, y[-1]
        while t < end:
            last = end - t <= step * (1 + 1e-9)
            h = end - t if last else step
            y = rk4(t + h / 2, rk4(t, y, h / 2), h / 2)
            t = end if last else t + h
        D.append(y[-1] - start)
    return np.array(D)


def test_fig9_chain_dissipation():
    D = dissipation_per_cycle(4)
    out = subprocess.run([fricreg_sim(), "chain", "--cycles", "4", "--error-estimate", "off"],
                         check=True, capture_output=True, text=True).stdout
    assert D.tobytes() == np.array(json.loads(out)["dissipation_per_cycle"]).tobytes()
    assert abs(D[3] - 0.0105) <= 5e-4 * 0.0105  # the paper's D; -0.04 % (docs/reproduction.md)
