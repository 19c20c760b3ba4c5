/* SPDX-License-Identifier: GPL-3.0-or-later */
/* cvode_setup.h — one CVODE integrator with root finding, set up and torn down in one place for
 * the event-driven references of the belt and the 2-D oscillator (belt_cvode.c, disk_cvode.c).
 * Built only with SUNDIALS (FRICREG_BENCH_CVODE). */
#ifndef FRICREG_BENCH_CVODE_SETUP_H
#define FRICREG_BENCH_CVODE_SETUP_H

#include <stddef.h>

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_config.h>

#if SUNDIALS_VERSION_MAJOR >= 7
typedef sunrealtype cv_real;
#else
typedef realtype cv_real;
#endif

/** The SUNDIALS objects of one run. */
struct cv_handle {
    SUNContext ctx;
    N_Vector y;
    SUNMatrix A;
    SUNLinearSolver LS;
    SUNNonlinearSolver NLS;
    void *mem;
};

/** Creates CVODE (method: enum ed_method, BDF with a dense Newton solver or Adams with
 *  fixed-point iteration) for dim unknowns starting at t = 0 from y = 0, rtol = atol, n_roots
 *  root functions, user data `user`. Returns 0, or -1 (h is then already closed). */
int cv_open(struct cv_handle *h, int method, size_t dim, CVRhsFn rhs, int n_roots, CVRootFn roots,
            void *user, double rtol);

/** Frees everything cv_open made; safe on a zeroed or closed handle. */
void cv_close(struct cv_handle *h);

/** CVODE's accepted steps since the last (re)initialization. */
double cv_steps(void *mem);

#endif
