/* sim_internal.h — the simulation's layout: a reference system (system.h) and the state of
 * its run (sim.c). */
#ifndef FRICREG_SIM_INTERNAL_H
#define FRICREG_SIM_INTERNAL_H

#include <stddef.h>
#include <stdint.h>

#include "error.h"
#include "fricreg_sim.h"
#include "system.h"

struct fricreg_sim {
    struct fr_system sys; /* the system and its parameters */
    int law;
    int partition; /* enum fricreg_partition, passed to the context */
    int running;   /* 1 while fricreg_sim_run steps: the observer may not change the run */
    int unguarded; /* tests only (test_guard.c, static library): skip the step guard, to see
                    * what a refused step would have done */
    double eps_set; /* 0: the paper's rule */
    int integrator;
    double dt, rtol, atol;
    fricreg_sim_observer observer;
    void *observer_user;

    /* Working state of a run, sized by the system at its start. */
    size_t ndof, m;
    double eps;
    fricreg_ctx *ctx;
    double *y;              /* [2 ndof + 1]: x, v, D */
    double *zdot, *a_free;  /* [m] contact kinematics */
    double *f, *f_eq;       /* [m] friction */
    double *stick_time;     /* [m] near-stick time in the current cycle */
    double *stick_fraction; /* [m] result */
    double *D;              /* [cycles] dissipation per cycle */
    double *jac_work;       /* [3 (2 ndof + 1)] finite-difference Jacobian scratch */
    size_t cycles;
    double t;
    int64_t steps, rhs_evals, rejected_steps; /* enum fricreg_sim_stat */
    int rhs_status;   /* fricreg status raised inside the right-hand side */
    size_t bad_contact; /* with FRICREG_ENONFINITE: the first contact that overflowed */

    struct fr_error err;
};

#endif
