#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""The Python binding's speed against C on the same work (docs/python.md, "Speed"): each task
run alternately by the C baseline (fricreg-bench-python-baseline, its own CPU clock) and from
Python (time.process_time around the binding's call), ROUNDS times each; the ratio of the
medians, measured in one run on one machine.

  hb       NLvib's chain swept with stability: HarmonicBalance + frequency_response
           against fricreg_hb_create .. fricreg_hb_continue and the points read (target <= 1.1);
  element  10^4 jenkins points: one Element.eval on arrays against 10^4 fricreg_element_eval
           calls (target <= 1.5).

Usage: PYTHONPATH=BUILD/python python3 bench/python_speed.py BUILD-BENCH/bench/fricreg-bench-python-baseline [ROUNDS]
"""
import statistics
import subprocess
import sys
import time

import numpy as np

import fricreg

TARGETS = {"hb": 1.1, "element": 1.5}
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


PYTHON = {"hb": hb_sweep, "element": element_points}


def c_seconds(baseline, task, reps):
    out = subprocess.run([baseline, task, str(reps)], check=True, capture_output=True,
                         text=True).stdout
    return [float(line.split()[1]) for line in out.splitlines()]


def python_seconds(task, reps):
    times = []
    for _ in range(reps):
        t0 = time.process_time()
        PYTHON[task]()
        times.append(time.process_time() - t0)
    return times


def main():
    baseline = sys.argv[1]
    rounds = int(sys.argv[2]) if len(sys.argv) > 2 else 7
    reps = {"hb": 3, "element": 50}
    print("task      C median (s)   Python median (s)   ratio   target")
    for task, target in TARGETS.items():
        c, py = [], []
        for _ in range(rounds):  # alternate, so that the machine's load falls on both
            c += c_seconds(baseline, task, reps[task])
            py += python_seconds(task, reps[task])
        ratio = statistics.median(py) / statistics.median(c)
        print("%-8s  %12.6f   %17.6f   %5.2f   <= %.1f %s" % (
            task, statistics.median(c), statistics.median(py), ratio, target,
            "" if ratio <= target else "(above)"))


if __name__ == "__main__":
    main()
