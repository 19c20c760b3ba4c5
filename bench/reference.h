/* SPDX-License-Identifier: GPL-3.0-or-later */
/* reference.h — the reference dissipation each benchmark error is measured against. */
#ifndef FRICREG_BENCH_REFERENCE_H
#define FRICREG_BENCH_REFERENCE_H

#include <stdio.h>

#include "bench.h"

/** A reference value of D on a problem's measured cycle, and how it was obtained. */
struct bench_reference {
    double D;           /* reference dissipation */
    double uncertainty; /* estimated absolute error of D */
    char how[240];      /* one line: the method */
};

/** Computes the reference of problem p, printing how (and, for a ladder, its convergence
 *  table) to log:
 *  - oscillators: the exact semi-analytical solution (fricreg_exact.h), uncertainty 1e-12 D;
 *  - chain and two blocks: law (4) with RK4 on a ladder of halved steps, eps by the paper's
 *    rule (10 omega dt, 2 dt), Richardson-extrapolated with the integer order nearest to
 *    the one the last three rungs show; the uncertainty is the difference between the
 *    extrapolations of the last two pairs of rungs.
 *  When the CVODE baseline is built, the classical event-driven solution at tight tolerance
 *  is printed beside it as an independent check (oscillators and chain).
 *  Returns FRICREG_OK or the failing run's status. */
int bench_reference(const struct bench_problem *p, struct bench_reference *ref, FILE *log);

#endif
