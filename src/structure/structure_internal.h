/* SPDX-License-Identifier: GPL-3.0-or-later */
/* structure_internal.h — the structure's layout, shared by its files. Each calls only files
 * above it in this list, never one below (tests/module_layers.sh): busy.c, changed.c (the
 * setters' one hook), contact_factor.c, contact_sparse.c, joint_storage.c, masked_factor.c,
 * step_pattern.c, warn_track.c (what the warnings judge, as the run steps); guard.c (the step guard), model.c
 * (the model matrices), newton_matrix.c, ode_tolerances.c; element_step.c (the elements' forces
 * and Newton), elements.c (the elements of any types), jenkins.c (the per-kind setters);
 * fundamental_frequency.c, prepare.c (the set-up of a model), step_newton.c, structure_gsl.c;
 * contact_step.c, energy.c (the balance); structure.c (life cycle, setters, getters);
 * forces.c (the forces of a state); central_difference.c, joint_step.c (elements beside
 * contacts); newmark.c; step.c (stepping, plain); structure_ode.c (GSL's steppers, plain);
 * error_estimate.c (the companions, stepped plain); blocks_carried.c (the near-stick block's
 * factor in a checkpoint); checkpoint.c, warnings.c (the checks);
 * run.c (the public stepping calls). */
#ifndef FRICREG_STRUCTURE_INTERNAL_H
#define FRICREG_STRUCTURE_INTERNAL_H

#include <math.h>
#include <stddef.h>
#include <stdint.h>

#include <cholmod.h>
#include <gsl/gsl_vector.h>

#include "base/error.h"
#include "base/warning.h"
#include "contact_factor.h"
#include "fricreg_element.h"
#include "fricreg_structure.h"
#include "newton_matrix.h"
#include "step_newton.h"

#define FR_NSSTATS 5

enum { FR_SCHEME_NEWMARK = 0, FR_SCHEME_CENTRAL = 1 }; /* HHT-alpha is Newmark's */

/* The model matrices, for fr_structure_install. */
enum { FR_MASS = 0, FR_STIFFNESS = 1, FR_DAMPING = 2, FR_CONTACTS = 3 };

/* A sampled time function: n samples from t0 every dt, linear, zero outside (n = 0: none). */
struct fr_record {
    double t0, dt;
    size_t n;
    double *x;
};

struct fr_energy {
    double initial, input, viscous, friction;
    double *per_contact; /* [m] */
    double jenkins;      /* the Jenkins elements' dissipation, all of them */
};

/* The elements (elements.c): me = 0 without any. Element i is of a type of fricreg_element.h
 * (its kernel, evaluated on the structure's state arrays as a host evaluates it on its own),
 * with its parameters at params + par[i] in the type's layout. Its dim components sit at the
 * element coordinates y = J_e u: its td tangential ones (td = dim without a normal law, dim - 1
 * with one) at at[i] .. at[i] + td - 1, among the nt tangential coordinates of all elements in
 * order, and its normal one, if it has one, at normal[i] (nc: none), after them; so the
 * coordinates of a set of one type are those of 1.x's setters: J_e's rows, then J_n's.
 * The structure receives -J^T fe, fe the elements' forces at their coordinates.
 * Each element's ns sliders have td positions each, its state: the slots slot[i] ..
 * slot[i + 1] - 1 of the slot arrays (wc, wt, fs, fs1: per slider, per axis, as the kernel's
 * state). Its tangent dfe/dy is the kernel's dfdu, dim x dim row-major at tb + blk[i]. */
/* The joint step's dense storage (joint_storage.c), for elements beside contacts of bound > 0:
 * m contacts, nc element coordinates, dim = m + nc; row-major. */
struct fr_joint {
    size_t m, nc, dim;
    int valid;                   /* Weff and W are the factors' (C and E: the elements' E_valid) */
    double *Weff, *W;            /* [m m] J K_eff^-1 J^T (as the step's sparse D) and J M^-1 J^T */
    double *C;                   /* [m nc] J K_eff^-1 J_e^T (J_e over J_n with a normal law) */
    double *T, *Fz, *Fa;         /* [dim dim] the Newton matrix; [m m] the context's tangent */
    double *tau, *norm, *rhs;    /* [dim] its QR and right-hand side */
    size_t *perm;                /* [dim] */
    double *z, *zt, *d;          /* [dim] the iterate (f, fe), the trial, the direction */
    double *gc, *gct, *ge, *get; /* [m], [m], [nc], [nc] residuals at z and at the trial */
    double *wf, *mf, *dzc;       /* [m] W_eff f, W f, the velocity change of d over c */
    double *coef, *fz, *wg;      /* [m] the context's rows, the slopes' signs, [W G_c] */
    unsigned char *implicit;     /* [m] */
    double *fe0, *dfe;           /* [nc] the elements' start forces, fe - fe0 */
};

struct fr_elements {
    size_t me, nc, nt, nslots;
    size_t ns; /* the sliders of every element if they all have as many, else 0 */
    int dim;   /* the tangential components of every element if they all have as many, else 0 */
    size_t nnormal;                    /* the elements with a normal law */
    const fricreg_element_type **type; /* [me] */
    size_t *at, *normal;               /* [me] the coordinates: tangential, normal (or nc) */
    size_t *par, *slot, *blk;          /* [me + 1] offsets into params, the slots, tb */
    size_t *owner;                     /* [nc] the element of a coordinate */
    double *params;                    /* [par[me]] */
    cholmod_sparse *Jt;                /* n x nc: J_e^T, then J_n^T */
    double *kstick;                    /* [nc] sum of k (all sticking), then kn (closed) */
    double *wc, *wt;                   /* [nslots] committed and trial slider positions */
    double *fs, *fs1;                  /* [nslots] slider forces at t and at the step's end */
    double *fe, *fe1;          /* [nc] element (then normal) forces at t and at the step's end */
    double *wc_held, *fs_held; /* [nslots] before a step's equilibrium, restored if it fails */
    double *fe_held;           /* [nc] */
    double *dissipation;       /* [me] since set_initial */
    double *q0, *y, *fy, *g, *df, *ft, *gt; /* [nc] Newton's scratch: fy = F(y) */
    double *tb;                             /* [blk[me]] the tangent blocks */
    double *tau, *norm;                     /* [nc] the Newton matrix's QR (GSL's, pivoted) */
    double *E, *A; /* [nc nc] J K_eff^-1 J^T for step_dt (J = J_e, or J_e over J_n), Newton's */
    size_t *perm;  /* [nc] its QR's permutation */
    int E_valid;   /* E is K_eff's at step_dt */
    int crossed;   /* the last committed step opened or closed an element: its energy is not
                      exact (warnings.c) */
    struct fr_joint joint; /* beside contacts of bound > 0 (joint_step.c) */

    /* The first element whose sliders' sums overflowed at the last fr_elements_residual:
     * 1 + its index (0: none), which sum ("force", "tangent" or "df/dg") and its value. */
    size_t overflow;
    const char *overflow_what;
    double overflow_sum;
};

struct fricreg_structure {
    size_t n, m;
    cholmod_common cc; /* CHOLMOD's workspace and settings (src/base/sparse_factor.h) */

    /* The model, as the caller gave it, in CHOLMOD's compressed columns. */
    cholmod_sparse *M, *K, *C; /* n x n, upper triangles (stype 1) */
    int rayleigh;              /* C = a0 M + a1 K, formed by fr_structure_prepare */
    double a0, a1;
    cholmod_sparse *Jt; /* n x m: J^T, column i contact i's row of J */
    int contacts_set;
    gsl_vector *r, *p;             /* influence and load pattern */
    struct fr_record ground, load; /* load.n == 0: g = 1 */
    fricreg_ctx *ctx;              /* law, eps, bounds; coupling set by fr_structure_prepare */
    double *mun;                   /* [m] the bounds, for the force scale */
    double bound_scale;            /* the largest entry of |J|^T mun (< 0: to be formed) */

    /* Integrator. */
    int scheme; /* FR_SCHEME_* */
    double alpha, beta, gamma;
    double newton_tol;
    int newton_max;
    int contact_solver; /* FRICREG_CONTACT_SOLVER_* (fricreg_structure_set_contact_solver) */

    /* Long runs: the observer, the bound on a run_ode call's adaptive steps (0: none), and
     * whether run or run_ode is stepping (the observer may then only read). */
    fricreg_structure_observer observer;
    void *observer_user;
    int64_t max_steps; /* -1: the law's default (fr_law_max_adaptive_steps) */
    int running;
    /* run_ode's absolute tolerances (ode_tolerances.c): those set per component (NULL: none),
     * what the last adaptive call asked for (for the getter), and the factor on the rule's
     * velocity level and on the set ones (1; the error estimate's companion: 1/16). */
    double *ode_atol; /* [2 n + 2 + m] or NULL */
    double ode_rtol;  /* the last adaptive run_ode call's rtol (0: none yet) */
    double ode_atol1; /* its atol: a scalar >= 0 or FRICREG_ATOL_FROM_EPS */
    double tol_scale;

    /* Derived at the first step after a model change (fr_structure_prepare). */
    int prepared;           /* Cd, the mass factor, W and Mr are current */
    cholmod_sparse *Cd;     /* the damping in force: C, or Rayleigh's a0 M + a1 K */
    struct fr_cfactor mass; /* M's factor; mass.D is the Delassus matrix W = J M^-1 J^T */
    int w_diagonal;         /* W has no entry off its diagonal (contacts on separate dofs) */
    gsl_vector *Mr;         /* M r */
    int unguarded;      /* tests only (test_guard_structure.c, static library): skip the step guard,
                    * to see what a refused step would have done */
    int omega_valid;    /* the step guard: omega_max, damping_max are current (reset by prepare) */
    double omega_max;   /* sqrt of the largest eigenvalue of M^-1 K (a bound for large models) */
    double damping_max; /* the largest eigenvalue of M^-1 C (a bound for large models) */
    int fundamental_valid; /* omega_min is current (reset with omega_valid) */
    double omega_min;  /* sqrt of M^-1 K_stick's smallest eigenvalue (0: not known; the warnings) */
    int stable;        /* K and C positive semidefinite (to rounding; large models: shown so) */
    int stick_valid;   /* the step guard: stick_rate is current (reset at equilibrium) */
    double stick_rate; /* lambda * eps (fr_stiffness_times_eps): the chord's for a law that jumps */

    /* Newmark's step: K_eff's factor (step.D = W_eff) for step_dt, and the Newton matrix. */
    struct fr_cfactor step;
    double step_dt; /* the dt K_eff was factored for (0: none) */
    struct fr_newton_matrix newton;
    struct fr_contact_sparse sparse; /* the near-stick blocks in the structure's space, for
                                        step_dt (contact_sparse.h; FRICREG_CONTACT_SOLVER_SPARSE) */

    /* State at time t; `ready` when a, f and p~ hold the equation of motion at t. */
    double t;
    gsl_vector *u, *v, *a;
    gsl_vector *ptil;            /* p - M r a_g at t */
    gsl_vector *f;               /* [m] friction at t */
    gsl_vector *a_held, *f_held; /* a and f before a step's equilibrium, restored if it fails */
    double end_max;              /* the largest |u1|, |v1|, |a1| of the step just solved (NaN
                                  * if one is NaN): the divergence check's */
    int ready;
    int fresh; /* set_initial since the last step: the balance starts here */
    /* The grid of the last fricreg_structure_run: its step k ended at clock_t0 + k clock_dt,
     * clock_k the last one taken (0: no run to continue, after step, run_ode or set_initial).
     * A run of the same dt that starts where that one ended continues its grid (step.c). */
    double clock_t0, clock_dt;
    int64_t clock_k;

    /* Step scratch, allocated at create: [n] ... */
    gsl_vector *x, *u1, *v1, *ptil1, *hist, *up, *vp, *work, *yb, *dx, *xt;
    gsl_vector *spread; /* [n] zero between uses (spread norms, the bounds' scale) */
    /* ... and [m]: the forces at the step's end, the context's inputs, Newton's iterate,
     * residual, direction, trial, and what the contacts see of the step's predictor. */
    gsl_vector *f1, *zdot, *afree, *fk, *G, *df, *ft, *Gt, *z0, *af0, *mwork, *mwork2;
    unsigned char *stopped; /* [m] Newton: stopped at zdot_i = 0 this step */
    /* W_eff f and W f at the step's start forces, Newton's iterate, its direction and the
     * trial (newmark.c): the residual is affine in f, so a trial's are combined, not formed */
    struct fr_compliance_pair at_start, at_fk, at_df, at_ft;

    struct fr_elements el;
    struct fr_energy energy;
    int64_t stats[FR_NSSTATS];
    struct fr_error err;

    /* The checks of plausibility (warnings.c): the list as last judged, and what the run
     * since set_initial showed them (reset by set_initial). */
    struct fr_warnings warnings;
    double peak_speed;     /* the largest |zdot_i| = |(J v)_i| at a step's end */
    double peak_dof_speed; /* the largest sum_j |J_ij| |v_j| at a step's end */
    double max_dt;         /* the longest fixed step (run_ode's adaptive ones aside) */
    int64_t inexact_steps; /* steps of a scheme whose energy balance is not exact */
    double ode_tol_level;  /* the loosest absolute part of a contact velocity's tolerance in
                            * an adaptive run_ode call, max_i sum_j |J_ij| atol_j (0: none) */
    double ode_rtol_max;   /* the largest rtol of those calls (0: none) */

    /* The largest |u_i| since set_initial (fricreg_structure_get_peak_displacement): every
     * step's end, fixed or adaptive, and its turning points between the ends (peak.c). [n] */
    double *peak;
    /* The error estimate (error_estimate.c): a companion structure at eps / 2 stepped alongside
     * at half the step (or tolerances / 16), made at the run's first step; with two companions
     * (estimate_on = FRICREG_ESTIMATE_TWO_COMPANIONS) the companion has its own, at eps / 4. */
    int estimate_on;              /* enum fricreg_error_estimate */
    int estimate_state;           /* FR_ESTIMATE_* */
    fricreg_structure *companion; /* while ACTIVE; else NULL, or stale until the next step */
    char estimate_msg[256];       /* why the estimate failed (FR_ESTIMATE_FAILED) */
    unsigned companion_pending;   /* enum fr_change: set since the companion last followed */
    double answer_rtol; /* fricreg_structure_set_answer_rtol: the estimate's warning level */
    /* fricreg_structure_set_error_companions: FRICREG_COMPANIONS_FINER (eps / 2, dt / 2, ...),
     * _COARSER (2 eps, 2 dt, ...) or _AUTO (coarser, then finer where they doubt) */
    int companions;
    /* The levels of `companion` and its own, FINER or COARSER: with AUTO, COARSER (the screen)
     * until the finer pair confirms. */
    int companion_level;
    /* AUTO's finer pair, made with the screen, kept at its start until the screen doubts or a
     * change is passed on (NULL otherwise); `parked` the stepping calls since its time (all
     * alike: a new kind of call first steps it to where the last ended). */
    fricreg_structure *confirm;
    struct fr_stepping_call {
        int integrator; /* 0: fixed steps (step, run) */
        double dt, rtol, atol;
    } parked;
    /* What the screen had said where the finer pair confirmed it: its estimates of the largest
     * peak's and of the summed dissipations' errors (+infinity: it failed; NaN: no confirmation) */
    double screen_peak_err, screen_dissipation_err;
    /* CPU seconds (clock()) in the companions' runs since the estimate's companion was made
     * (FRICREG_SVALUE_COMPANION_CPU): the first companion's call, its own companion's inside */
    double companion_cpu;
};

enum {
    FR_ESTIMATE_NONE = 0,   /* off, not started since set_initial, or ended by a setter */
    FR_ESTIMATE_ACTIVE = 1, /* the companion follows the structure */
    FR_ESTIMATE_FAILED = 2  /* the companion failed: the estimates are +infinity */
};

/* ode_tolerances.c */
/* The absolute tolerances atol[2 n + 2 + m] of an adaptive run_ode call with rtol and atol
 * (a scalar or FRICREG_ATOL_FROM_EPS) and the weights w[2 n + 2 + m] of rtol per component:
 * the set ones (w = 1), the rule from eps, or atol in every component (w = 1). w may be NULL. */
void fr_ode_tolerances(const fricreg_structure *s, double rtol, double atol, double out[],
                       double w[]);

/* structure.c */
/* The status of a refused call `who`: FRICREG_ENULL for s NULL (nothing recorded), FRICREG_EINVAL
 * (recorded) for a call made from the observer during a run. */
int fr_structure_refuse(fricreg_structure *s, const char *who);

/* With a warning handler installed, judges the checks now (fricreg_structure_warning_count),
 * which hands the handler the warnings it has not had since set_initial (warnings.c). */
void fr_structure_judge_for_handler(fricreg_structure *s);
double fr_record_at(const struct fr_record *rec, double t);
/* A record's peak |x| and the peak of its integral (trapezoidal from t0): for the ground
 * acceleration, the peak ground acceleration and velocity; 0 without samples. */
void fr_record_peaks(const struct fr_record *rec, double *peak, double *peak_integral);
void fr_structure_effective_load(const fricreg_structure *s, double t, gsl_vector *ptil);

/* model.c: installs A as the model matrix `which` (FR_MASS, FR_STIFFNESS, FR_DAMPING: n x n,
 * upper triangle; FR_CONTACTS: J, m x n) after the checks that matrix needs (the mass
 * positive definite, every contact moving); takes A, freed on failure too. The message of a
 * failure is led by who. */
int fr_structure_install(fricreg_structure *s, int which, cholmod_sparse *A, const char *who);

/* changed.c: what a setter changed, for fr_structure_changed. The changes to what the error
 * estimate's companion copied (FR_CHANGES_RECOPIED) end the estimate until the next run's start;
 * the others are passed on to the companion at the next stepping call (fr_estimate_sync). */
enum fr_change {
    FR_CHANGED_MODEL = 1u << 0,   /* M, K, C, J, Rayleigh, the elements: the set-up anew */
    FR_CHANGED_SCHEME = 1u << 1,  /* Newmark, HHT or central difference: K_eff anew */
    FR_CHANGED_INITIAL = 1u << 2, /* set_initial: a new run */
    FR_CHANGED_BOUNDS = 1u << 3,  /* the equilibrium at t anew */
    FR_CHANGED_LAW = 1u << 4,     /* the equilibrium at t anew; the companion's eps is half */
    FR_CHANGED_NEWTON = 1u << 5,  /* and those below: read at the next step */
    FR_CHANGED_MAX_STEPS = 1u << 6,
    FR_CHANGED_ODE_ATOL = 1u << 7,
    FR_CHANGED_GROUND = 1u << 8,
    FR_CHANGED_LOAD = 1u << 9
};
#define FR_CHANGES_RECOPIED (FR_CHANGED_MODEL | FR_CHANGED_SCHEME | FR_CHANGED_INITIAL)
/* The one hook of every setter that changes the structure: `what` an OR of enum fr_change. */
void fr_structure_changed(fricreg_structure *s, unsigned what);

/* prepare.c: the set-up of a model at its first step (the damping in force, M's factor, W into
 * the context, M r, the force scale); and am M + ac C + ak K, the upper triangle, or NULL when
 * out of memory. */
int fr_structure_prepare(fricreg_structure *s);
cholmod_sparse *fr_structure_combine(fricreg_structure *s, double am, double ac, double ak);

/* Newton's merit, a sum of squares of forces, that overflows only where its square root does:
 * the plain sum (bit for bit the merit's old value) while it is finite, else the sum of the
 * entries scaled by 2^-600 (exact: a power of two), so that forces beyond 1e154 N still give
 * a finite merit. NaN propagates. */
struct fr_sumsq {
    double sum, scaled;
};

static inline void fr_sumsq_add(struct fr_sumsq *a, double x)
{
    double y = x * 0x1p-600;
    a->sum += x * x;
    a->scaled += y * y;
}

/* The square root of the sum: sqrt(sum), or sqrt(scaled) 2^600 where sum overflowed. */
static inline double fr_sumsq_root(const struct fr_sumsq *a)
{
    return isinf(a->sum) ? sqrt(a->scaled) * 0x1p600 : sqrt(a->sum);
}

/* sqrt(a^2 + b^2) as sqrt of the sum while that is finite (the old bits), else hypot. */
static inline double fr_merit_pair(double a, double b)
{
    double sum = a * a + b * b;
    return isinf(sum) ? hypot(a, b) : sqrt(sum);
}

/* step.c: one step of dt, and a run of fixed steps dt to t_end, plain: the public calls'
 * checks and results but the error estimate and the warning handler (run.c). */
int fr_structure_step_plain(fricreg_structure *s, double dt);
int fr_structure_run_plain(fricreg_structure *s, double dt, double t_end);
/* peak.c: the peaks take in a fixed step of length h from the current state to u1[n], v1[n],
 * its turning points included (step). */
void fr_peak_step(fricreg_structure *s, const double u1[], const double v1[], double h);
/* The observer (if any) at time t with u[n], v[n], f[m]: 1 if it asks to stop. */
int fr_structure_observe(fricreg_structure *s, double t, const double u[], const double v[],
                         const double f[]);
/* structure_ode.c: fricreg_structure_run_ode, plain (as step.c's). */
int fr_structure_run_ode_plain(fricreg_structure *s, int integrator, double dt, double rtol,
                               double atol, double t_end);

/* forces.c */
double fr_norm_inf(const gsl_vector *x);
/* The acceleration and friction at t from the equation of motion (the elements' forces at
 * equilibrium with the state): a step's start after set_initial, a setter or run_ode. */
int fr_structure_equilibrium(fricreg_structure *s);
/* The context's forces f[m] at s->zdot and s->afree: FRICREG_OK, or the context's status (an
 * input that is not finite, which the structure's own state made: FRICREG_EDIVERGED). */
int fr_structure_contact_forces(fricreg_structure *s, gsl_vector *f);
/* The friction f[m] and the acceleration a[n] of a state of velocity v whose net force but
 * friction is w = p~ - C v - K u: zdot = J v, a_free = J M^-1 w, f from the context, then
 * M a = w + J^T f (one forward and one backward solve with M's factor). Uses s->yb. */
int fr_structure_motion(fricreg_structure *s, const gsl_vector *w, const gsl_vector *v,
                        gsl_vector *f, gsl_vector *a);
/* The 2-norm and the largest entry of scale J^T G[m] (nonzero on the degrees of freedom J
 * touches only: O(nnz(J)), through s->spread). */
void fr_structure_spread_norms(fricreg_structure *s, double scale, const gsl_vector *G,
                               double *norm2, double *norm_inf);
/* w = p~ - C v - K u */
void fr_structure_net_force(const fricreg_structure *s, const gsl_vector *ptil, const gsl_vector *u,
                            const gsl_vector *v, gsl_vector *w);

/* The largest of m and |x|, NaN if either is: a running maximum for end_max. */
static inline double fr_max_abs(double m, double x)
{
    double a = x < 0.0 ? -x : x;
    return a <= m || m != m ? m : a; /* a NaN x, or a NaN m from an earlier x, gives NaN */
}

/* newmark.c: u1, v1, x (= a1), f1 and end_max of one Newmark / HHT-alpha step by Newton. */
int fr_newmark_solve(fricreg_structure *s, double dt, int *converged, int *iters);
/* K_eff's factor for dt, exactly (a restored structure's, checkpoint.c): FRICREG_OK or the
 * factorization's failure (recorded). */
int fr_newmark_factor(fricreg_structure *s, double dt);

/* central_difference.c: the same, explicit; FRICREG_ESTEP beyond its stability bounds. */
int fr_central_solve(fricreg_structure *s, double dt);

/* guard.c: what the step guard (src/ode/step_guard.h) reads of the model, computed once per
 * model by fr_structure_rates (FRICREG_OK or FRICREG_ENOMEM, recorded, led by who), read
 * after it: the largest natural frequency sqrt(max eig M^-1 K) (0 if K has none > 0), whether
 * K and C are positive semidefinite (to rounding), the stiffest rate of run_ode's Jacobian; and
 * the step guard of a fixed step dt of integ, FRICREG_OK or FRICREG_ESTEP (recorded). Up to
 * 2048 degrees of freedom the eigenvalues themselves; beyond, Gershgorin bounds (guard.c). */
struct fr_integrator;
int fr_structure_rates(fricreg_structure *s, const char *who);
int fr_structure_stable(const fricreg_structure *s);
/* K + J^T diag(kstick) J, the stiffness with every element sticking and closed (its upper
 * triangle), or NULL when out of memory. */
cholmod_sparse *fr_structure_stick_stiffness(fricreg_structure *s);
/* Both caches above and the fundamental frequency's stale: the model or its elements changed. */
void fr_structure_rates_stale(fricreg_structure *s);

/* fundamental_frequency.c: omega_1 = sqrt of the smallest eigenvalue of K_stick x = lambda M x
 * (every element sticking), rad/s, by inverse iteration on K_stick's Cholesky factor, cached
 * until the model changes; 0 where not known (K_stick not positive definite: a rigid-body
 * mode; no memory). For the warnings' dt check. */
double fr_structure_fundamental_omega(fricreg_structure *s);
/* A bound of the stiffest rate in the forward-difference Jacobian J of run_ode's first-order
 * system: omega_max + c_max + m max_i W_ii 2 mun_i / max(eps, sqrt(DBL_EPSILON)), the friction's
 * steepest slope as a forward difference of step >= sqrt(DBL_EPSILON) |y| sees it (a law's
 * jump included). GSL's LU-based steppers factor I - h c J: once h times it nears
 * 1/DBL_EPSILON, the identity is lost to rounding and the factor can be exactly singular. */
double fr_structure_newton_rate(const fricreg_structure *s);
int fr_structure_guard(fricreg_structure *s, const struct fr_integrator *integ, double dt,
                       const char *who);

/* warn_track.c: what a step of length dt (0: an adaptive one) shows the checks (warnings.c),
 * ode for one of run_ode's (GSL's schemes: their energy balance is not exact); reset with the
 * run (set_initial). */
void fr_warn_track_step(fricreg_structure *s, double dt, int ode);
void fr_warn_track_reset(fricreg_structure *s);
void fr_warn_track_ode_tolerances(fricreg_structure *s, double rtol, double atol);

/* element_step.c: the elements' part of the step. elements_equilibrium: fe at q = J_e u from wc
 * (committed: the mapping is idempotent), w -= J_e^T fe. elements_explicit: fe1, wt at
 * J_e u1, w -= J_e^T fe1 (central difference); both FRICREG_ENONFINITE where an element's
 * sliders' sum overflows. elements_newmark: Newton on fe1 with b[n] the
 * step's right-hand side K_eff x = b - w J_e^T fe1 (before the forward solve), until max |G|
 * is within newton_tol times the larger of scale and max |fe|; then b -= (1 + alpha) J_e^T fe1. elements_commit after an accepted step. */
int fr_elements_compliance(fricreg_structure *s, int joint);
/* G = fe - F(y) at the coordinates e->y (formed by the caller), into g[nc]; the tangents into
 * e->tb, the trial sliders into e->wt, e->fs1; returns ||G||_2, *rinf its largest entry (NaN
 * propagates). An element whose sliders' sums overflow is recorded in e->overflow
 * (fr_elements_overflow reports it). */
double fr_elements_residual(struct fr_elements *e, const double fe[], double g[], double *rinf);
/* Row k of the tangent dfe/dy at the last fr_elements_residual, as its nonzero pattern: the
 * columns into col[] and the entries into val[], the diagonal first, then the element's other
 * tangential coordinates in order, then its normal one (the order in which the Newton
 * matrices sum them); returns their count, 1 to 3. */
int fr_elements_tangent_row(const struct fr_elements *e, size_t k, size_t col[3], double val[3]);
int fr_elements_equilibrium(fricreg_structure *s, gsl_vector *w);
int fr_elements_explicit(fricreg_structure *s, const gsl_vector *u1, gsl_vector *w, double t);
int fr_elements_newmark(fricreg_structure *s, double dt, double scale, gsl_vector *b,
                        int *converged, int *iters);
void fr_elements_commit(fricreg_structure *s);
/* Newton's forces f[nc] onto the elements' bounds: |f_i| <= sum phi_s N_i (N_i = 1 without a
 * normal law, else f's normal force, first raised to 0 if below), radially for a 2-D element.
 * Newton stops within tol of the return mapping's F_e(q), which is on the bound while slipping
 * (a 2-D iterate on the circle's tangent, outside it): the iterate can be beyond the bound.
 * Projecting onto the convex bound moves it towards F_e(q) (with a normal law, to within the
 * tolerance of N), and leaves a force within its bound bit for bit. */
void fr_elements_bound(const struct fr_elements *e, double f[]);
/* FRICREG_ENONFINITE with a message naming the element whose sums overflowed at the last
 * fr_elements_residual (at time t), or FRICREG_OK if none did. */
int fr_elements_overflow(fricreg_structure *s, double t);
/* fe and wc into their held copies (restore = 0), or back (restore = 1). */
void fr_elements_hold(fricreg_structure *s, int restore);
void fr_elements_reset(fricreg_structure *s);
void fr_elements_free(fricreg_structure *s);
double fr_elements_strain(const fricreg_structure *s);
/* Some contact has a bound > 0 beside elements: the step is joint_step.c's. */
int fr_elements_joint(const fricreg_structure *s);

/* joint_storage.c: allocate: the dense storage for m contacts and nc coordinates (kept if the
 * sizes hold), 0 when out of memory; compliances: W_eff and W dense from the factors (C and E
 * are element_step.c's). */
int fr_joint_allocate(struct fr_joint *j, size_t m, size_t nc);
void fr_joint_compliances(fricreg_structure *s);
void fr_joint_free(struct fr_joint *j);
/* joint_step.c: the step's Newton over the contacts' and the elements' forces together, with
 * newmark.c's predictor formed at (f = 0, fe = fe at t): z0, a0, e->q0; from the forces at t,
 * or guess[m] (the contacts' stick guess, NULL: none) with the elements' at t, until both
 * residuals' largest entries are within tol; the forces into s->fk and e->fe1, the law's at
 * them into s->f1, the sliders' trial state at them. */
int fr_joint_newton(fricreg_structure *s, double tol, const double guess[], int *converged,
                    int *iters);

/* energy.c */
void fr_energy_reset(fricreg_structure *s);
void fr_energy_start(fricreg_structure *s);
void fr_energy_step(fricreg_structure *s, const gsl_vector *u1, const gsl_vector *v1,
                    const gsl_vector *ptil1, const gsl_vector *f1);
double fr_energy_kinetic(const fricreg_structure *s);
double fr_energy_strain(const fricreg_structure *s);

/* estimate_companions.c. estimate_begin: at a stepping call's start, makes the companion if the
 * estimate is on and the run starts there (and frees a stale one). estimate_follow: at the
 * call's end, passes the setters' changes on (estimate_sync) and steps the companion to the
 * structure's time with the call's scheme: fixed steps dt / 2 (integrator 0: the structure's
 * own scheme), an adaptive GSL run the tolerances / 16; a refusal or a failure makes the
 * estimate a failed one. estimate_sync: checkpoint.c's too, before a save. */
void fr_estimate_begin(fricreg_structure *s);
/* A new companion of s at the levels `level` (FRICREG_COMPANIONS_FINER or _COARSER), a copy
 * of its configuration and state as fr_estimate_begin makes it,
 * into *out: FRICREG_OK, or FRICREG_ENOMEM and the companion's failure's message into
 * msg[256] (nothing made). */
int fr_estimate_companion(const fricreg_structure *s, int level, fricreg_structure **out,
                          char msg[]);
void fr_estimate_follow(fricreg_structure *s, int integrator, double dt, double rtol, double atol);
void fr_estimate_sync(fricreg_structure *s);
void fr_estimate_check(fricreg_structure *s); /* warnings.c's check of the estimate */
/* 1 where the estimate now would raise FRICREG_WARN_ERROR_ESTIMATE (fr_estimate_check's test),
 * else 0; the largest peak's and the summed dissipations' estimates into *peak_err and
 * *dissipation_err. For an active estimate only. */
int fr_estimate_doubts(const fricreg_structure *s, double *peak_err, double *dissipation_err);
/* The estimates of s's peak i, contact j's dissipation and joint element i's dissipation, their
 * kinds into *kind (enum fricreg_estimate_kind), from the companions of an active estimate. */
double fr_estimate_peak(const fricreg_structure *s, size_t i, int *kind);
double fr_estimate_dissipation(const fricreg_structure *s, size_t j, int *kind);
double fr_estimate_element_dissipation(const fricreg_structure *s, size_t i, int *kind);
/* estimate_companions.c: where FRICREG_COMPANIONS_AUTO's screen doubts now (fr_estimate_doubts)
 * and the run is not under way, the parked finer pair steps to s's time and gives the estimate
 * from here on (a failure fails the estimate); otherwise nothing. Every read of the estimate
 * calls it first (estimate_read.c, values.c, warnings.c). */
void fr_estimate_settle(fricreg_structure *s);

/* elements.c: the elements of types[me] with their params (each its type's nparams, in order)
 * on Jt (n x nc in the coordinates' order: taken, freed here on every path), in place of those
 * s holds, every slider at w = 0. FRICREG_OK; FRICREG_ENOMEM (recorded, under who). */
int fr_elements_install(fricreg_structure *s, size_t me, const fricreg_element_type *const types[],
                        const double params[], cholmod_sparse *Jt, const char *who);
/* elements.c: element i's dim components of the coordinates' array x[nc] into out[dim]
 * (tangential, then normal), and back. */
void fr_elements_gather(const struct fr_elements *e, size_t i, const double x[], double out[]);
void fr_elements_scatter(const struct fr_elements *e, size_t i, const double in[], double x[]);
/* elements.c: a copy of src's elements on dst (the companion), sliders at w = 0. */
int fr_elements_clone(fricreg_structure *dst, const fricreg_structure *src);

#endif
