#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""The Python binding's speed against C on the same work (docs/python.md, "Speed"): each task
run alternately by the C baseline (fricreg-bench-python-baseline, its own CPU clock) and from
Python (time.process_time around the binding's call), in ROUNDS rounds of a few repetitions
each side; a round's ratio is of its sides' fastest, and the median over the rounds is
printed (the load of this shared machine drifts by tens of percent within seconds: a round's
two sides see the same load). The times printed are the medians of the rounds' fastest.

  hb       NLvib's chain swept with stability: HarmonicBalance + frequency_response
           against fricreg_hb_create .. fricreg_hb_continue and the points read (target <= 1.1);
  element  10^4 jenkins points: one Element.eval on arrays against 10^4 fricreg_element_eval
           calls (target <= 1.5);
  structure  the README's ten-storey building (examples/building, its error estimate on):
           Structure + run against fricreg-sim structure's own CPU clock (cpu_seconds) on the
           same model's Matrix Market files (target <= 1.05).

Usage: PYTHONPATH=BUILD/python python3 bench/python_speed.py BUILD [ROUNDS], BUILD a tree
configured with -DFRICREG_BENCH=ON (its bench/fricreg-bench-python-baseline, fricreg-sim and
examples/make_building).
"""
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

# One BLAS thread on both sides: these problems are too small to share, and OpenBLAS's idle
# threads spin, which doubles the CPU clock of both sides by amounts that differ run to run.
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
import numpy as np  # noqa: E402 (after the BLAS threads are set)

import fricreg  # noqa: E402

TARGETS = {"hb": 1.1, "element": 1.5, "structure": 1.05}
K = np.array([[2.0, -1.0, 0.0], [-1.0, 2.0, -1.0], [0.0, -1.0, 2.0]])
J = np.array([[1.0, 0.0, 0.0], [-1.0, 1.0, 0.0]])
N = 10000
U = np.linspace(-1.0, 1.0, N)[:, None]  # python_baseline.c's points
W = 0.1 * U * U
JENKINS = fricreg.Element("jenkins", [2.0, 0.5])


def hb_sweep():
    hb = fricreg.HarmonicBalance(np.eye(3), K, 0.02 * K, harmonics=7,
                                 elements=[(fricreg.Element("jenkins", [20.0, 1.0]), J)],
                                 excitation=([0.0, 1.0, 0.0], None))
    hb.set_stability(True)
    return hb.frequency_response(0.5, 2.0)


def element_points():
    return JENKINS.eval(U, W)


def building():
    """examples/python/structure_building.py's model and run (make_building's numbers)."""
    n, mass, k, g = 10, 1e5, 1e8, 9.81
    K = 2 * k * np.eye(n) - k * np.eye(n, k=1) - k * np.eye(n, k=-1)
    K[-1, -1] = k
    t = 1e-3 * np.arange(10001)
    ag = 0.3 * g * np.sin(np.pi * t / 10) * np.sin(2 * np.pi * t)
    w0 = 2 * np.sqrt(k / mass)
    w1, w2 = (w0 * np.sin(j * np.pi / (2 * (2 * n + 1))) for j in (1, 3))
    s = fricreg.Structure(mass * np.eye(n), K, rayleigh=(0.1 * w1 * w2 / (w1 + w2), 0.1 / (w1 + w2)),
                          J=np.eye(n) - np.eye(n, k=-1), mun=0.05 * g * mass * (n - np.arange(n)),
                          eps=0.01, ground_accel=(0.0, 1e-3, ag), error_estimate="on")
    return s.run("newmark", dt=0.01, t_end=15.0)


PYTHON = {"hb": hb_sweep, "element": element_points, "structure": building}


def c_seconds(build, task, reps, files):
    """The C side's CPU seconds per repetition: the baseline's own clock, or fricreg-sim's
    (its summary's cpu_seconds, the model set up from its arrays and the run, the files read
    before it, plus companion_cpu_seconds, the error estimate's companions) for the
    structure."""
    if task != "structure":
        out = subprocess.run([os.path.join(build, "bench", "fricreg-bench-python-baseline"),
                              task, str(reps)], check=True, capture_output=True, text=True).stdout
        return [float(line.split()[1]) for line in out.splitlines()]
    rayleigh = open(os.path.join(files, "rayleigh.txt")).read().strip()
    command = [os.path.join(build, "fricreg-sim"), "structure", "--mass", files + "/M.mtx",
               "--stiffness", files + "/K.mtx", "--rayleigh", rayleigh, "--contacts",
               files + "/J.mtx", "--mun", files + "/mun.txt", "--ground-accel",
               files + "/ground.txt", "--eps", "0.01", "--integrator", "newmark", "--dt", "0.01",
               "--t-end", "15"]
    times = []
    for _ in range(reps):
        out = subprocess.run(command, check=True, capture_output=True, text=True).stdout
        summary = json.loads(out)  # the run's clock, and since 1.9 its companions' apart
        times.append(summary["cpu_seconds"] + summary.get("companion_cpu_seconds", 0.0))
    return times


def python_seconds(task, reps):
    times = []
    for _ in range(reps):
        t0 = time.process_time()
        PYTHON[task]()
        times.append(time.process_time() - t0)
    return times


def main():
    build = sys.argv[1]
    rounds = int(sys.argv[2]) if len(sys.argv) > 2 else 7
    reps = {"hb": 3, "element": 50, "structure": 2}
    files = tempfile.mkdtemp(prefix="fricreg-building.")
    subprocess.run([os.path.join(build, "examples", "make_building"), files], check=True,
                   capture_output=True)
    print("task        C (s)          Python (s)          ratio   target")
    for task, target in TARGETS.items():
        c, py, ratios = [], [], []
        for _ in range(rounds):  # alternate, so that the machine's load falls on both
            c.append(min(c_seconds(build, task, reps[task], files)))
            py.append(min(python_seconds(task, reps[task])))
            ratios.append(py[-1] / c[-1])  # a round's pair: the machine's drift cancels
        ratio = statistics.median(ratios)
        print("%-10s  %12.6f   %17.6f   %5.2f   <= %.2f %s" % (
            task, statistics.median(c), statistics.median(py), ratio, target,
            "" if ratio <= target else "(above)"))


if __name__ == "__main__":
    main()
