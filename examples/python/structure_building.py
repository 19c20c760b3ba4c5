#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""The ten-storey building of examples/building (docs/structural.md, "The ten-storey
building") from Python: storey mass 1e5 kg, storey stiffness 1e8 N/m, 5 % Rayleigh damping in
modes 1 and 2, a friction damper on every storey drift slipping at 5 % of the weight above,
and the ground acceleration 0.3 g sin(pi t/10) sin(2 pi t) for 10 s, then 5 s free; Newmark's
average acceleration at dt = 0.01 s, law (4) with eps = 0.01 m/s, and the error estimate of
two companion runs at (eps/2, dt/2) and (eps/4, dt/4).

It checks docs/structural.md's numbers (peak roof 0.2224 m, damper energy 1.542 MJ, the
energy balance closed to rounding, no warning, the estimates within 1 % of their quantities)
and writes structure_building.csv (t, the roof's and floor 1's displacements, damper 1's
force) always and structure_building.png (the roof against time, damper 1's hysteresis loop)
where matplotlib is installed. Run: PYTHONPATH=build/python python3 structure_building.py
"""
import warnings

import numpy as np

import fricreg

n, mass, k, g = 10, 1e5, 1e8, 9.81
K = 2 * k * np.eye(n) - k * np.eye(n, k=1) - k * np.eye(n, k=-1)
K[-1, -1] = k                               # the top floor has one spring
J = np.eye(n) - np.eye(n, k=-1)             # damper i slides with the drift u_i - u_(i-1)
mun = 0.05 * g * mass * (n - np.arange(n))  # 5 % of the weight of floors i .. top (N)
t = 1e-3 * np.arange(10001)                 # the record: 1 ms samples for 10 s
ag = 0.3 * g * np.sin(np.pi * t / 10) * np.sin(2 * np.pi * t)
w0 = 2 * np.sqrt(k / mass)                  # modes 1, 2 of the fixed-free shear chain
w1, w2 = (w0 * np.sin(j * np.pi / (2 * (2 * n + 1))) for j in (1, 3))
rayleigh = (2 * 0.05 * w1 * w2 / (w1 + w2), 2 * 0.05 / (w1 + w2))

building = fricreg.Structure(mass * np.eye(n), K, rayleigh=rayleigh, J=J, mun=mun, eps=0.01,
                             ground_accel=(0.0, 1e-3, ag), error_estimate="on")
with warnings.catch_warnings():
    warnings.simplefilter("error", fricreg.AccuracyWarning)  # in SI units: none
    run = building.run("newmark", dt=0.01, t_end=15.0, output_dofs=[9, 0])

roof, energy = run.peak_displacement[-1], run.energy
print("peak roof displacement %.7f m +- %.2g (%s)"
      % (roof, run.peak_displacement_error.error[-1], run.peak_displacement_error.kind[-1]))
print("damper energy %.6g J (each: %s)" % (energy["friction"], np.array2string(
    run.dissipation, precision=4)))
print("energy residual / input %.2g, Newton %d iterations in %d steps, %d failures"
      % (energy["residual"] / energy["input"], run.stats["newton_iterations"],
         run.stats["steps"], run.stats["newton_failures"]))
assert abs(roof - 0.2223898) < 1e-6 and abs(energy["friction"] - 1.542442e6) < 2.0
assert abs(energy["residual"]) < 1e-12 * energy["input"] and run.stats["newton_failures"] == 0
assert run.peak_displacement_error.error.max() < 0.01 * roof
assert run.dissipation_error.error.sum() < 0.01 * run.dissipation.sum()
assert run.warnings == []

np.savetxt("structure_building.csv",
           np.column_stack([run.times, run.displacements, run.forces[:, 0]]), delimiter=",",
           header="t,u10,u1,f1", comments="")
try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    print("matplotlib not installed: structure_building.csv only")
else:
    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4))
    left.plot(run.times, run.displacements[:, 0])
    left.set_xlabel("t (s)")
    left.set_ylabel("roof displacement (m)")
    right.plot(run.displacements[:, 1], run.forces[:, 0] / 1e3)
    right.set_xlabel("storey 1 drift (m)")
    right.set_ylabel("damper 1 force (kN)")
    fig.tight_layout()
    fig.savefig("structure_building.png", dpi=100)
    print("wrote structure_building.csv and structure_building.png")
