/* SPDX-License-Identifier: GPL-3.0-or-later */
/* central_step.c — explicit central differences (src/ode/central.h, the scheme the structure's
 * central difference shares) as a gsl_odeiv2_step_type, for fricreg_sim's fixed steps
 * (FRICREG_INT_CENTRAL and FRICREG_INT_CENTRAL_IMEX).
 *
 * The state is fricreg_sim's (src/sim/sim.c): y = (x[n], v[n], D), dim = 2n + 1, and the
 * right-hand side returns (v, a, D'). One step of size h, with a = a(t, x, v) carried over from
 * the end of the previous step, is central.h's, and D's increment
 *
 *   D1 = D - w h/2 sum_i (f_i + f1_i)/2 (zdot_i + zdot1_i)/2   (w: the system's weight),
 *
 * f, f1 the friction forces of the two evaluations and zdot, zdot1 the contact velocities of
 * the state's v and v1 (not v*). The stability bound, (dt omega/2)^2 + dt lambda < 1, is
 * derived in src/ode/step_guard.c. FRICREG_INT_CENTRAL_IMEX ("central-imex") is the same step
 * with the friction taken at v1 itself, law (4) solved body by body (central_imex.c), which
 * frees the step from the stick zone's bound.
 *
 * D is the work of the step's mean friction impulse on its mean velocity: since v1 - v is h
 * times the mean acceleration, this is exactly the friction's share of the scheme's own change
 * of kinetic energy, so E + D balances the forcing's work to the scheme's spring-energy error.
 * The trapezoid of D' = -w zdot.f that the right-hand side returns would see v*, which in the
 * stick zone overshoots: at the paper's eps = 2 dt it overcounted D by 1.1 of an energy scale
 * of 3.8 on the unforced oscillator (law (3), dt = 0.71; tests/ode/test_guard.c's balance).
 * So the stepper reads the friction the right-hand side leaves in the simulation
 * (sim_internal.h): it serves fricreg_sim only.
 *
 * The error estimate is zero: fixed steps only (fricreg_sim_set_integrator refuses tolerances). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_errno.h>

#include "central_imex.h"
#include "central_step.h"
#include "ctx/ctx_driver.h"
#include "base/dispatch.h"
#include "ode/central.h"
#include "ode/integrator.h"
#include "sim_internal.h"
#include "base/free_all.h"

struct central_state {
    double *dydt;  /* [dim] (v, a, D') at the start of the step: the last step's end */
    double *next;  /* [dim] the same at the step's end */
    double *arg;   /* [dim] (x1, v*, D) where the right-hand side is evaluated */
    double *f;     /* [m <= dim] friction forces of dydt's evaluation */
    double *zdot;  /* [m] contact velocities of the state at the step's start */
    double t_dydt; /* the time dydt belongs to */
    int have_dydt; /* 0 after alloc and reset: dydt is evaluated at the next step's start */
    double h_arg;  /* > 0: arg already holds the predictor of a step of h_arg from the state */
    /* central-imex only: fr_central_imex_coefficients [3 m] for the step h_coef (0: none) */
    double *coef;
    double h_coef;
};

static void central_free(void *vstate)
{
    struct central_state *s = vstate;
    if (s == NULL)
        return;
    FR_FREE_ALL(s->dydt, s->next, s->arg, s->f, s->zdot, s->coef, s);
}

static void *central_alloc(size_t dim)
{
    struct central_state *s = calloc(1, sizeof *s);
    if (s == NULL)
        return NULL;
    s->dydt = malloc(dim * sizeof *s->dydt);
    s->next = malloc(dim * sizeof *s->next);
    s->arg = malloc(dim * sizeof *s->arg);
    s->f = malloc(dim * sizeof *s->f); /* m <= ndof < dim for every reference system */
    s->zdot = malloc(dim * sizeof *s->zdot);
    s->coef = malloc(3 * dim * sizeof *s->coef);
    if (!s->dydt || !s->next || !s->arg || !s->f || !s->zdot || !s->coef) {
        central_free(s);
        return NULL;
    }
    return s;
}

/* The carried acceleration belongs to this step's start: the same run, the time the last step
 * ended (fricreg_sim sets a cycle's end time exactly, within rounding of t + h). */
static int carried_dydt_valid(const struct central_state *s, double t, double h)
{
    return s->have_dydt && fabs(t - s->t_dydt) <= 1e-9 * fabs(h);
}

/* The evaluation point (x1, v*, D) of the step from y with derivative d = (v_used, a, D'). */
static void predictor(size_t n, double h, const double *restrict y, const double *restrict d,
                      double *restrict arg)
{
    const double *x = y, *v = y + n, *a = d + n;
    for (size_t i = 0; i < n; i++) {
        arg[i] = fr_central_position(h, x[i], v[i], a[i]);
        arg[n + i] = fr_central_predicted_velocity(h, v[i], a[i]);
    }
    arg[2 * n] = y[2 * n]; /* D: the right-hand side does not read it */
}

/* x = x1 and v by the trapezoid on the carried and the new acceleration. */
static void corrector(size_t n, double h, const double *restrict arg, const double *restrict d0,
                      const double *restrict d1, double *restrict y)
{
    for (size_t i = 0; i < n; i++) {
        y[i] = arg[i];
        y[n + i] = fr_central_velocity(h, y[n + i], d0[n + i], d1[n + i]);
    }
}

/* The contact velocities of the state y at t (the simulation's buffer or y's v). */
static const double *contact_velocities(fricreg_sim *sim, double t, const double y[])
{
    return sim->sys.type->contacts(&sim->sys, t, y, y + sim->ndof, sim->zdot_buf, NULL);
}

/* D's increment over the step (the file's comment), from the carried f and zdot and the new
 * f1 = sim->f and zdot1; then f1 and zdot1 are carried on. */
enum { WORK_LANES = 4 }; /* partial sums: one running sum is a serial add per contact */
static double dissipation_step(fricreg_sim *sim, struct central_state *s, double h,
                               const double *restrict zdot1)
{
    double *restrict f0 = s->f, *restrict zdot0 = s->zdot;
    const double *restrict f1 = sim->f;
    double lane[WORK_LANES] = {0.0}, work = 0.0;
    size_t m = sim->m, i = 0;
    for (; i + WORK_LANES <= m; i += WORK_LANES)
        for (size_t l = 0; l < WORK_LANES; l++)
            lane[l] += (f0[i + l] + f1[i + l]) * (zdot0[i + l] + zdot1[i + l]);
    for (; i < m; i++)
        lane[0] += (f0[i] + f1[i]) * (zdot0[i] + zdot1[i]);
    for (size_t l = 0; l < WORK_LANES; l++)
        work += lane[l];
    memcpy(f0, f1, m * sizeof *f0);
    memcpy(zdot0, zdot1, m * sizeof *zdot0);
    return -0.25 * h * sim->sys.type->dissipation_weight(&sim->sys) * work;
}

/* The loop of bodies_end_pass (finish_on_bodies) over n bodies, from v = y's v at the step's
 * start: writes x1 and v1 into x and v and f1 into f0 (carried on), adds h to stick where
 * |v1| < eps, and overwrites (x1, v*) with the predictor of the next step, of the same h
 * (predictor(), from x1, v1 and a1: the same operations, so the same bits). Returns
 * sum_i (f0_i + f1_i)(v_i + v1_i) and the count of components of (x1, v1) beyond
 * FR_SIM_STATE_LIMIT or not finite in *diverged. restrict: GCC honours it on parameters,
 * which lets the pass vectorize. */
enum { END_LANES = 8 }; /* 4 made GCC 12 shuffle and spill: 2.3 ns a body, 8 1.1 */
FR_KERNEL_BODY double bodies_end_loop(size_t n, double h, double eps, double *restrict x1,
                                      double *restrict vstar, const double *restrict a0,
                                      const double *restrict a1, const double *restrict f1,
                                      double *restrict f0, double *restrict stick,
                                      double *restrict x, double *restrict v, double *diverged)
{
    double lane[END_LANES] = {0.0}, bad[END_LANES] = {0.0}, work = 0.0, limit = FR_SIM_STATE_LIMIT;
    size_t i = 0;
#define FR_BODY_END(k, l)                                                               \
    do {                                                                                \
        double v1 = fr_central_velocity(h, v[k], a0[k], a1[k]);                         \
        lane[l] += (f0[k] + f1[k]) * (v[k] + v1);                                       \
        f0[k] = f1[k];                                                                  \
        stick[k] += fabs(v1) < eps ? h : 0.0;                                           \
        bad[l] += (fabs(x1[k]) <= limit ? 0.0 : 1.0) + (fabs(v1) <= limit ? 0.0 : 1.0); \
        x[k] = x1[k];                                                                   \
        v[k] = v1;                                                                      \
        x1[k] = fr_central_position(h, x[k], v1, a1[k]);                                \
        vstar[k] = fr_central_predicted_velocity(h, v1, a1[k]);                         \
    } while (0)
    for (; i + END_LANES <= n; i += END_LANES)
        for (size_t l = 0; l < END_LANES; l++)
            FR_BODY_END(i + l, l);
    for (; i < n; i++) /* the tail */
        FR_BODY_END(i, 0);
#undef FR_BODY_END
    *diverged = 0.0;
    for (size_t l = 0; l < END_LANES; l++) {
        work += lane[l];
        *diverged += bad[l];
    }
    return work;
}

#ifdef FRICREG_AVX2_DISPATCH
FR_AVX2 static double bodies_end_avx2(size_t n, double h, double eps, double *restrict x1,
                                      double *restrict vstar, const double *restrict a0,
                                      const double *restrict a1, const double *restrict f1,
                                      double *restrict f0, double *restrict stick,
                                      double *restrict x, double *restrict v, double *diverged)
{
    return bodies_end_loop(n, h, eps, x1, vstar, a0, a1, f1, f0, stick, x, v, diverged);
}
#endif

/* bodies_end_loop, in AVX2 where the CPU has it (dispatch.h). */
static double bodies_end_pass(size_t n, double h, double eps, double *restrict x1,
                              double *restrict vstar, const double *restrict a0,
                              const double *restrict a1, const double *restrict f1,
                              double *restrict f0, double *restrict stick, double *restrict x,
                              double *restrict v, double *diverged)
{
#ifdef FRICREG_AVX2_DISPATCH
    if (fr_have_avx2())
        return bodies_end_avx2(n, h, eps, x1, vstar, a0, a1, f1, f0, stick, x, v, diverged);
#endif
    return bodies_end_loop(n, h, eps, x1, vstar, a0, a1, f1, f0, stick, x, v, diverged);
}

/* The loop of imex_friction_pass: the friction at the step's end solved implicitly, body by
 * body (central_imex.h), from the state's v, the carried a0, the free accelerations a_free at
 * the step's end and coef = (bound_acc, den_inv, w_inv) [3n] of fr_central_imex_coefficients:
 * f1 and a1 = a_free + W f1. A pass of its own: fused into bodies_end_pass, the step took
 * 1.4x as long (chain, n = 1000, SSE2: 14 streams in one loop). */
FR_KERNEL_BODY void imex_friction_loop(size_t n, double h, double eps, const double *restrict v,
                                       const double *restrict a0, const double *restrict a_free,
                                       const double *restrict coef, double *restrict f1,
                                       double *restrict a1)
{
    double two_over_eps = 2.0 / eps;
    const double *bound_acc = coef, *den_inv = coef + n, *w_inv = coef + 2 * n;
    for (size_t i = 0; i < n; i++) {
        double g1 = fr_imex_friction_acc(v[i], a0[i], a_free[i], h, two_over_eps, bound_acc[i],
                                         den_inv[i]);
        a1[i] = a_free[i] + g1;
        f1[i] = g1 * w_inv[i];
    }
}

#ifdef FRICREG_AVX2_DISPATCH
FR_AVX2 static void imex_friction_avx2(size_t n, double h, double eps, const double *restrict v,
                                       const double *restrict a0, const double *restrict a_free,
                                       const double *restrict coef, double *restrict f1,
                                       double *restrict a1)
{
    imex_friction_loop(n, h, eps, v, a0, a_free, coef, f1, a1);
}
#endif

/* imex_friction_loop, in AVX2 where the CPU has it (dispatch.h). */
static void imex_friction_pass(size_t n, double h, double eps, const double *restrict v,
                               const double *restrict a0, const double *restrict a_free,
                               const double *restrict coef, double *restrict f1,
                               double *restrict a1)
{
#ifdef FRICREG_AVX2_DISPATCH
    if (fr_have_avx2()) {
        imex_friction_avx2(n, h, eps, v, a0, a_free, coef, f1, a1);
        return;
    }
#endif
    imex_friction_loop(n, h, eps, v, a0, a_free, coef, f1, a1);
}

/* The step's end when the contacts are the bodies (zdot = v: the oscillator, the chain), in
 * one pass (bodies_end_pass): the corrector, D's increment (dissipation_step with zdot = v,
 * so the carried zdot is y's v itself and no copy of it is kept), the carried f, sim.c's
 * after-step checks (the diverged components, the near-stick time) and the next step's
 * predictor. Returns D's increment. */
static double finish_on_bodies(fricreg_sim *sim, struct central_state *s, double h, double y[])
{
    size_t n = sim->ndof;
    double diverged = 0.0;
    double work = bodies_end_pass(n, h, sim->eps, s->arg, s->arg + n, s->dydt + n, s->next + n,
                                  sim->f, s->f, sim->stick_time, y, y + n, &diverged);
    s->h_arg = h;
    double dD = -0.25 * h * sim->sys.type->dissipation_weight(&sim->sys) * work;
    diverged += fabs(y[2 * n] + dD) <= FR_SIM_STATE_LIMIT ? 0.0 : 1.0;
    sim->step_diverged = (size_t)diverged;
    sim->step_checked = 1;
    return dD;
}

/* The step's end for any system: the corrector, then D's increment. */
static double finish_any(fricreg_sim *sim, struct central_state *s, double t, double h, double y[])
{
    corrector(sim->ndof, h, s->arg, s->dydt, s->next, y);
    return dissipation_step(sim, s, h, contact_velocities(sim, t + h, y));
}

/* The step's end, explicit: the right-hand side at (t + h, x1, v*) into s->next, then the
 * corrector and D's increment (returned into *dD). GSL's status. */
static int explicit_end(const gsl_odeiv2_system *sys, struct central_state *s, double t, double h,
                        double y[], double *dD)
{
    fricreg_sim *sim = sys->params;
    size_t n = sim->ndof;
    int status = GSL_ODEIV_FN_EVAL(sys, t + h, s->arg, s->next);
    if (status != GSL_SUCCESS)
        return status;
    /* The evaluation read the contact velocities straight from its v*: the contacts are
     * the bodies (system.h's contacts()). */
    int on_bodies = sim->zdot == s->arg + n && sim->m == n;
    *dD = on_bodies ? finish_on_bodies(sim, s, h, y) : finish_any(sim, s, t, h, y);
    return GSL_SUCCESS;
}

/* The step's end with implicit friction (central_imex.c), where fr_central_imex_refusal
 * allows it (law (4), contacts the bodies, W diagonal): the free accelerations at
 * (t + h, x1), the friction solved body by body (imex_friction_pass: f1 into sim->f, a1
 * into s->next), and the end of finish_on_bodies. Never fails. */
static int implicit_end(const gsl_odeiv2_system *sys, struct central_state *s, double t, double h,
                        double y[], double *dD)
{
    fricreg_sim *sim = sys->params;
    const fricreg_ctx *ctx = sim->ctx;
    size_t n = sim->ndof;
    sim->rhs_evals++;
    sim->sys.type->contacts(&sim->sys, t + h, s->arg, s->arg + n, sim->zdot_buf, sim->a_free);
    if (s->h_coef != h) { /* once per step size: at a run's start and each cycle's end */
        fr_central_imex_coefficients(n, h, fr_ctx_eps(ctx), fr_ctx_bounds(ctx),
                                     fr_ctx_coupling_diagonal(ctx), s->coef);
        s->h_coef = h;
    }
    imex_friction_pass(n, h, fr_ctx_eps(ctx), y + n, s->dydt + n, sim->a_free, s->coef, sim->f,
                       s->next + n);
    *dD = finish_on_bodies(sim, s, h, y);
    return GSL_SUCCESS;
}

typedef int step_end(const gsl_odeiv2_system *sys, struct central_state *s, double t, double h,
                     double y[], double *dD);

/* One step; on failure y is left as it was. yerr may be NULL (sim.c's direct call). */
static int central_step(void *vstate, size_t dim, double t, double h, double y[], double yerr[],
                        const gsl_odeiv2_system *sys, step_end *end)
{
    struct central_state *s = vstate;
    fricreg_sim *sim = sys->params;
    if (dim != 2 * sim->ndof + 1 || sim->m > dim)
        return GSL_EBADLEN; /* not fricreg_sim's layout (x, v, D) */
    size_t n = sim->ndof;
    if (!carried_dydt_valid(s, t, h)) {
        int status = GSL_ODEIV_FN_EVAL(sys, t, y, s->dydt);
        if (status != GSL_SUCCESS)
            return status;
        memcpy(s->f, sim->f, sim->m * sizeof *s->f);
        memcpy(s->zdot, sim->zdot, sim->m * sizeof *s->zdot); /* of (t, y) itself */
        s->have_dydt = 1;
        s->t_dydt = t;
        s->h_arg = 0.0;
    }
    if (s->h_arg != h) /* else the last step's end made it */
        predictor(n, h, y, s->dydt, s->arg);
    s->h_arg = 0.0;
    double dD = 0.0;
    int status = end(sys, s, t, h, y, &dD);
    if (status != GSL_SUCCESS)
        return status;
    y[2 * n] += dD;
    double *swap = s->dydt; /* a1 is the next step's a */
    s->dydt = s->next;
    s->next = swap;
    s->t_dydt = t + h;
    if (yerr != NULL)
        memset(yerr, 0, dim * sizeof *yerr);
    return GSL_SUCCESS;
}

static int central_apply(void *vstate, size_t dim, double t, double h, double y[], double yerr[],
                         const double dydt_in[], double dydt_out[], const gsl_odeiv2_system *sys)
{
    (void)dydt_in, (void)dydt_out; /* can_use_dydt_in = gives_exact_dydt_out = 0 */
    return central_step(vstate, dim, t, h, y, yerr, sys, explicit_end);
}

static int central_imex_apply(void *vstate, size_t dim, double t, double h, double y[],
                              double yerr[], const double dydt_in[], double dydt_out[],
                              const gsl_odeiv2_system *sys)
{
    (void)dydt_in, (void)dydt_out;
    return central_step(vstate, dim, t, h, y, yerr, sys, implicit_end);
}

static int central_reset(void *vstate, size_t dim)
{
    (void)dim;
    ((struct central_state *)vstate)->have_dydt = 0;
    ((struct central_state *)vstate)->h_arg = 0.0;
    ((struct central_state *)vstate)->h_coef = 0.0;
    return GSL_SUCCESS;
}

static unsigned int central_order(void *vstate)
{
    (void)vstate;
    return 2;
}

static int central_set_driver(void *vstate, const gsl_odeiv2_driver *d)
{
    (void)vstate, (void)d;
    return GSL_SUCCESS;
}

static const gsl_odeiv2_step_type central_type = {
    "central",     0,           0, central_alloc, central_apply, central_set_driver, central_reset,
    central_order, central_free};

const gsl_odeiv2_step_type *fr_step_central(void)
{
    return &central_type;
}

static const gsl_odeiv2_step_type central_imex_type = {"central-imex",
                                                       0,
                                                       0,
                                                       central_alloc,
                                                       central_imex_apply,
                                                       central_set_driver,
                                                       central_reset,
                                                       central_order,
                                                       central_free};

const gsl_odeiv2_step_type *fr_step_central_imex(void)
{
    return &central_imex_type;
}
