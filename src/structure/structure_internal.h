/* SPDX-License-Identifier: GPL-3.0-or-later */
/* structure_internal.h — the structure's layout, shared by structure.c (model, set-up),
 * newmark.c (the integrator and Newton) and energy.c (the balance). */
#ifndef FRICREG_STRUCTURE_INTERNAL_H
#define FRICREG_STRUCTURE_INTERNAL_H

#include <stddef.h>
#include <stdint.h>

#include <gsl/gsl_eigen.h>
#include <gsl/gsl_matrix.h>
#include <gsl/gsl_permutation.h>
#include <gsl/gsl_vector.h>

#include "base/error.h"
#include "fricreg_structure.h"

#define FR_NSSTATS 5

enum { FR_SCHEME_NEWMARK = 0, FR_SCHEME_CENTRAL = 1 }; /* HHT-alpha is Newmark's */

/* A sampled time function: n samples from t0 every dt, linear, zero outside (n = 0: none). */
struct fr_record {
    double t0, dt;
    size_t n;
    double *x;
};

struct fr_energy {
    double initial, input, viscous, friction;
    double *per_contact; /* [m] */
};

struct fricreg_structure {
    size_t n, m;

    /* The model, as the caller gave it. */
    gsl_matrix *M, *K, *C; /* n x n; C is formed from a0, a1 when rayleigh */
    int rayleigh;
    double a0, a1;
    gsl_matrix *J; /* m x n */
    int contacts_set;
    gsl_vector *r, *p;             /* influence and load pattern */
    struct fr_record ground, load; /* load.n == 0: g = 1 */
    fricreg_ctx *ctx;              /* law, eps, bounds; coupling set by fr_structure_prepare */
    double *mun;                   /* [m] the bounds, for the force scale */

    /* Integrator. */
    int scheme; /* FR_SCHEME_* */
    double alpha, beta, gamma;
    double newton_tol;
    int newton_max;

    /* Long runs: the observer, the bound on a run_ode call's adaptive steps (0: none), and
     * whether run or run_ode is stepping (the observer may then only read). */
    fricreg_structure_observer observer;
    void *observer_user;
    int64_t max_steps; /* -1: the law's default (fr_law_max_adaptive_steps) */
    int running;

    /* Derived at the first step after a model change (fr_structure_prepare). */
    int prepared;       /* M's factor, G, W and C are current */
    gsl_matrix *L;      /* n x n: Cholesky factor of M */
    gsl_matrix *G;      /* m x n: J M^-1 */
    gsl_matrix *W;      /* m x m: J M^-1 J^T */
    gsl_vector *Mr;     /* M r */
    int unguarded;      /* tests only (test_guard_structure.c, static library): skip the step guard,
                    * to see what a refused step would have done */
    int omega_valid;    /* the step guard: omega_max, damping_max are current (reset by prepare) */
    double omega_max;   /* sqrt of the largest eigenvalue of M^-1 K */
    double damping_max; /* the largest eigenvalue of M^-1 C */
    int stable;         /* K and C positive semidefinite (to rounding) */
    int stick_valid;    /* the step guard: stick_rate is current (reset at equilibrium) */
    double stick_rate; /* lambda * eps (fr_stiffness_times_eps): the chord's for a law that jumps */
    gsl_eigen_symm_workspace *eigen_work;
    gsl_vector *eigenvalues;

    /* State at time t; `ready` when a, f and p~ hold the equation of motion at t. */
    double t;
    gsl_vector *u, *v, *a;
    gsl_vector *ptil;            /* p - M r a_g at t */
    gsl_vector *f;               /* [m] friction at t */
    gsl_vector *a_held, *f_held; /* a and f before a step's equilibrium, restored if it fails */
    int ready;
    int fresh; /* set_initial since the last step: the balance starts here */

    /* Newton scratch, allocated at create. */
    gsl_matrix *S, *GS; /* n x n: gamma dt C + beta dt^2 K; m x n: G S */
    double S_dt;        /* the dt S was formed for (0: none) */
    gsl_matrix *A;      /* n x n: the Newton matrix, then its QR with column pivoting */
    gsl_permutation *perm;
    gsl_vector *tau, *norm;  /* [n] the QR's Householder coefficients, column norms */
    gsl_matrix *Fz, *Fa;     /* m x m: df/dzdot, df/da_free */
    gsl_matrix *T1;          /* m x n: gamma dt F_z J - F_a G S */
    gsl_vector *x, *dx, *xt; /* unknown a, direction, trial */
    gsl_vector *u1, *v1, *guess, *R, *Rt, *ptil1, *hist, *up, *vp, *work;
    gsl_vector *f1, *zdot, *afree, *mwork; /* [m] */
    unsigned char *stopped;                /* [m] Newton: stopped at zdot_i = 0 this step */
    size_t *stick_perm;                    /* [m] the stick predictor's pivots */

    struct fr_energy energy;
    int64_t stats[FR_NSSTATS];
    struct fr_error err;
};

/* structure.c */
int fr_structure_prepare(fricreg_structure *s);
/* The refusal of a call `who` made from the observer during a run: FRICREG_EINVAL, recorded. */
int fr_structure_busy(fricreg_structure *s, const char *who);
double fr_record_at(const struct fr_record *rec, double t);
void fr_structure_effective_load(const fricreg_structure *s, double t, gsl_vector *ptil);

/* step.c */
double fr_norm_inf(const gsl_vector *x);
/* The observer (if any) at time t with u[n], v[n], f[m]: 1 if it asks to stop. */
int fr_structure_observe(fricreg_structure *s, double t, const double u[], const double v[],
                         const double f[]);
int fr_structure_equilibrium(fricreg_structure *s);
/* a_free = G w, zdot = J v, f from the context, for the net non-friction force w. */
int fr_structure_friction(fricreg_structure *s, const gsl_vector *w, const gsl_vector *v,
                          gsl_vector *f);
/* w = p~ - C v - K u */
void fr_structure_net_force(const fricreg_structure *s, const gsl_vector *ptil, const gsl_vector *u,
                            const gsl_vector *v, gsl_vector *w);

/* newmark.c: u1, v1, x (= a1) and f1 of one Newmark / HHT-alpha step by Newton. */
int fr_newmark_solve(fricreg_structure *s, double dt, int *converged, int *iters);

/* stick_predictor.c: the contacts whose force at t is below their bound (law (4): in its
 * band), marked in s->stopped; their number. */
size_t fr_stick_mark(fricreg_structure *s);
/* A first guess for a Newmark / HHT-alpha step's Newton, from the k marked contacts, into
 * s->guess; 0 if there is none (k = 0, or W_SS singular). Uses s->Fa, s->afree, s->mwork. */
int fr_stick_predictor(fricreg_structure *s, size_t k);

/* central_difference.c: the same, explicit; FRICREG_ESTEP beyond its stability bounds. */
int fr_central_solve(fricreg_structure *s, double dt);

/* guard.c: the largest natural frequency sqrt(max eig M^-1 K) (0 if K has none > 0), cached;
 * and the step guard (src/ode/step_guard.h) of a fixed step dt of integ, FRICREG_OK or
 * FRICREG_ESTEP (recorded, led by who). */
struct fr_integrator;
double fr_structure_omega_max(fricreg_structure *s);
/* K and C are positive semidefinite, to rounding (cached with omega_max). */
int fr_structure_stable(fricreg_structure *s);
/* A bound of the stiffest rate in the forward-difference Jacobian J of run_ode's first-order
 * system: omega_max + c_max + m max_i W_ii 2 mun_i / max(eps, sqrt(DBL_EPSILON)), the friction's
 * steepest slope as a forward difference of step >= sqrt(DBL_EPSILON) |y| sees it (a law's
 * jump included). GSL's LU-based steppers factor I - h c J: once h times it nears
 * 1/DBL_EPSILON, the identity is lost to rounding and the factor can be exactly singular. */
double fr_structure_newton_rate(fricreg_structure *s);
int fr_structure_guard(fricreg_structure *s, const struct fr_integrator *integ, double dt,
                       const char *who);

/* energy.c */
void fr_energy_reset(fricreg_structure *s);
void fr_energy_start(fricreg_structure *s);
void fr_energy_step(fricreg_structure *s, const gsl_vector *u1, const gsl_vector *v1,
                    const gsl_vector *ptil1, const gsl_vector *f1);
double fr_energy_kinetic(const fricreg_structure *s);
double fr_energy_strain(const fricreg_structure *s);

#endif
