/* SPDX-License-Identifier: GPL-3.0-or-later */
/* sim_internal.h — the simulation's layout: a reference system (system.h) and the state of
 * its run (sim.c). */
#ifndef FRICREG_SIM_INTERNAL_H
#define FRICREG_SIM_INTERNAL_H

#include <stddef.h>
#include <stdint.h>

#include "base/error.h"
#include "base/warning.h"
#include "fricreg_sim.h"
#include "richardson.h"
#include "system.h"

/* |state| beyond this: diverged, an unstable step on its way to overflow (integrate.c's after-step
 * check; central_step.c's fused pass). */
#define FR_SIM_STATE_LIMIT 1e100

struct fr_kinks; /* kinks.c */

/* The rule from eps's velocity tolerance, per unit of eps (tolerances.c; and the
 * warning against looser ones, warnings.c). */
#define FR_SIM_ATOL_V_PER_EPS 1e-3

struct fricreg_sim {
    struct fr_system sys; /* the system and its parameters */
    int law;
    int partition;  /* enum fricreg_partition, passed to the context */
    int running;    /* 1 while fricreg_sim_run steps: the observer may not change the run */
    int unguarded;  /* tests only (test_guard.c, static library): skip the step guard, to see
                    * what a refused step would have done */
    double eps_set; /* 0: the paper's rule */
    int integrator;
    double dt, rtol, atol;
    /* The absolute tolerances of an adaptive run, one of: atol for every component (atol_vec
     * NULL, atol_from_eps 0); fricreg's rule from eps (atol_from_eps 1: tolerances.c);
     * the caller's per component (atol_vec [atol_n = 2 ndof + 1], owned). The rule's velocity
     * tolerance is scaled by rule_scale: 1, or an error estimate's companion's tolerance scale,
     * so that all of the companion's tolerances are tightened together (fr_sim_level). */
    int atol_from_eps;
    double rule_scale;
    double *atol_vec;
    size_t atol_n;
    int64_t max_steps; /* adaptive steps of one forcing cycle (0: no bound; -1: the law's) */
    int kink_location; /* adaptive steps stop at the law's kinks (kinks.c); 1 by default */
    fricreg_sim_observer observer;
    void *observer_user;

    /* Working state of a run, sized by the system at its start. */
    size_t ndof, m;
    double eps;
    fricreg_ctx *ctx;
    double *y;               /* [2 ndof + 1]: x, v, D */
    double *zdot_buf;        /* [m] contact velocities, for systems that do not pass v */
    const double *zdot;      /* [m] the last evaluation's contact velocities: zdot_buf or v */
    double *a_free;          /* [m] free accelerations */
    double *f, *f_eq;        /* [m] friction */
    double *stick_time;      /* [m] near-stick time in the current cycle */
    double *stick_fraction;  /* [m] result */
    double *D;               /* [cycles] dissipation per cycle */
    double *jac_work;        /* [3 (2 ndof + 1)] finite-difference Jacobian scratch */
    struct fr_jacobian *jac; /* the analytic Jacobian's maps, made at its first use */
    size_t cycles;
    double t;
    int64_t steps, rhs_evals, rejected_steps, kinks; /* enum fricreg_sim_stat */
    struct fr_kinks *locate;  /* kinks.c: during an adaptive run with kink location, else NULL */
    int rhs_status;           /* fricreg status raised inside the right-hand side */
    size_t bad_contact;       /* with FRICREG_ENONFINITE: the first contact that overflowed */
    struct fr_extrap *extrap; /* extrapolate.c: the last fricreg_sim_run_extrapolated */
    /* error_estimate.c: the setting (fricreg_sim_set_error_estimate), and the last run's
     * estimate: per cycle [cycles] and of the total D, NULL / NaN when none is held;
     * estimate_failed (with its message) when the companion run failed. */
    int error_estimate;
    int estimate_skip; /* set by extrapolate.c for its level 0: the extrapolation estimates */
    double *D_err;
    double total_err;
    int *D_kind; /* [cycles + 1] with D_err: enum fricreg_estimate_kind, per cycle, the total's */
    int estimate_failed;
    char estimate_msg[200];
    double answer_rtol; /* fricreg_sim_set_answer_rtol: the estimate's warning level */
    /* Set by a step that made the after-step checks in its own last pass (central_step.c):
     * it counted the diverged components into step_diverged and added the step to
     * stick_time, so after_step skips its two passes over the state. */
    int step_checked;
    size_t step_diverged;
    /* Set for the run of a fixed step of fricreg's own explicit steppers (rk4, central), which
     * never fail a step and whose state after_step checks: the right-hand side then skips the
     * context's finiteness pass (fr_ctx_eval_unchecked), a non-finite input reaching the
     * state instead. */
    int unchecked_eval;

    /* extrapolate.c's window (fricreg_sim_run_extrapolated_window), kept across free_run: a
     * run that starts at the end of cycle start_cycle from the state start_y (x, v; D starts
     * at 0) and records only the cycles after it; a run that copies its state (x, v, D) at
     * the end of cycle capture_cycle into capture_y. 0 and NULL: neither. */
    size_t start_cycle, capture_cycle;
    const double *start_y; /* [2 ndof] */
    double *capture_y;     /* [2 ndof + 1] */

    struct fr_error err;
    struct fr_warnings warnings; /* the checks of plausibility, as last judged (warnings.c) */
};

/* rhs.c: the right-hand side of the ODE y = (x, v, D) for gsl_odeiv2_system (params: the
 * fricreg_sim). Leaves the contacts' zdot, a_free and f of (t, y) in the simulation and the
 * context. GSL_EBADFUNC, with sim->rhs_status set, if the context refuses the state. */
int fr_sim_rhs(double t, const double y[], double dydt[], void *params);

/* rhs.c: the contacts' kinematics and friction at (t, x, v) into sim->zdot, a_free, f (and
 * f_eq with want_feq); the context's status. */
int fr_sim_eval_friction(fricreg_sim *sim, double t, const double y[], int want_feq);

/* sim.c: one run to t_end from the initial state, its results in sim: fricreg_sim_run without
 * the error estimate and the warnings' delivery (run.c), for the companions and levels that
 * have neither. */
int fr_sim_run_plain(fricreg_sim *sim, double t_end);

/* settings.c: a setter or a run called from the observer would free or replace the state the run
 * is stepping: refused (FRICREG_EINVAL, recorded), and the run goes on. `who` names the
 * call. For sim NULL: FRICREG_ENULL, nothing recorded. */
int fr_sim_refuse_during_run(fricreg_sim *sim, const char *who);

/* sim_jacobian.c: the Jacobian dfdy [dim x dim, row-major] and dfdt [dim] of fr_sim_rhs, for
 * gsl_odeiv2_system, dim = 2 ndof + 1. fr_sim_jacobian is analytic (the system's linear maps
 * through fricreg_ctx_tangent), or fr_sim_jacobian_fd for a system without maps;
 * fr_sim_jacobian_fd is by forward differences. Both leave the context at an evaluation of
 * (t, y) or a nearby state, and fail as fr_sim_rhs does; fr_sim_jacobian also with
 * GSL_ENOMEM (rhs_status FRICREG_ENOMEM) when it cannot allocate its maps. */
struct fr_jacobian;
int fr_sim_jacobian(double t, const double y[], double *dfdy, double dfdt[], void *params);
int fr_sim_jacobian_fd(double t, const double y[], double *dfdy, double dfdt[], void *params);
void fr_jacobian_free(struct fr_jacobian *J);

/* An extrapolation's results (extrapolate.c fills them), held by the simulation until its
 * next run. */
struct fr_extrap {
    int levels;
    size_t cycles;
    double *D, *D_err; /* [cycles] */
    struct fr_richardson total;
    size_t first;    /* the first extrapolated cycle (0 unless a window) */
    int order;       /* of the last whole cycle (else of the total) */
    double observed; /* likewise */
    size_t flagged;  /* whole cycles flagged */
    double eps_finest;
    int64_t rhs_evals; /* all levels */
};

/* settings.c: releases an extrapolation (NULL: nothing), as fr_sim_free_run discards it. */
void fr_extrap_free(struct fr_extrap *x);

/* level.c: a new simulation with every setting of sim at level k: eps / 2^k, a fixed
 * step dt / 2^k, and an adaptive run's tolerances (rtol, atol, per component) times
 * tol_scale with its first step kept. FRICREG_OK or FRICREG_ENOMEM; *out is then the
 * caller's. */
int fr_sim_level(const fricreg_sim *sim, int k, double tol_scale, fricreg_sim **out);

/* error_estimate.c: after a successful run of sim with the estimate on, the companion run
 * and the estimate per cycle (a failed companion leaves +infinity and its message for the
 * warning); fr_sim_check_estimate raises the estimate's warnings (warnings.c). */
void fr_sim_error_estimate(fricreg_sim *sim);
/* The rule from eps's absolute tolerance of a velocity at eps (tolerances.c). */
double fr_sim_rule_atol_v(const fricreg_sim *sim, double eps);
/* What an adaptive run's tolerances ask of the dissipation D: atol_D + rtol |D| (tolerances.c). */
double fr_sim_dissipation_tolerance(const fricreg_sim *sim, double D);
void fr_sim_check_estimate(fricreg_sim *sim);

/* With a warning handler installed, judges the checks now (fricreg_sim_warning_count), which
 * hands the handler the warnings it has not had since the run began (warnings.c). */
void fr_sim_judge_for_handler(fricreg_sim *sim);

#endif
