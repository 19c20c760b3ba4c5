/* SPDX-License-Identifier: GPL-3.0-or-later */
/* event_driven.h — the baseline users pick instead of regularizing: classical Coulomb
 * friction (1) with force balance at rest (2), integrated by SUNDIALS CVODE between events
 * that its root finding locates on the stick/slip switching functions.
 *
 * Built only when CMake finds SUNDIALS (Debian: libsundials-dev); FRICREG_BENCH_CVODE is then
 * defined. Handles the problems with uncoupled contacts (W = I): the oscillator and the
 * chain. */
#ifndef FRICREG_BENCH_EVENT_DRIVEN_H
#define FRICREG_BENCH_EVENT_DRIVEN_H

#include "bench.h"

/** CVODE's two method families. */
enum ed_method { ED_BDF = 1, ED_ADAMS = 2 };

/** One event-driven run. */
struct ed_point {
    const struct bench_problem *problem; /* problem->event_driven must be 1 */
    int method;                          /* enum ed_method */
    double rtol;                         /* CVODE reltol */
    double cpu_cap; /* CPU seconds after which the run stops and fails, saying how far it
                     * got (checked at every event and cycle boundary); 0: no cap */
    double atol;    /* CVODE abstol, the same for every component; 0: abstol = rtol */
};

/** bench_fn for a struct ed_point: D on problem->cycle, CVODE's steps, right-hand-side
 *  evaluations (its difference-quotient Jacobian's included) and the number of mode
 *  switches. Returns FRICREG_OK, FRICREG_EINTEGRATOR if CVODE fails or the CPU cap is reached
 *  (out->msg says why, and how far it got),
 *  FRICREG_EINVAL for a problem it does not handle, FRICREG_ENOMEM. */
int ed_run(const void *point, struct bench_run *out);

/** "SUNDIALS x.y.z" of the headers built against. */
const char *ed_version(void);

#endif
