/* SPDX-License-Identifier: GPL-3.0-or-later */
/* rk4_classic.c — the classical fourth-order Runge–Kutta step as a gsl_odeiv2_step_type.
 *
 * GSL's own "rk4" estimates its error by step doubling: a call with step 2h returns two
 * classical steps of h for 12 right-hand sides. A fixed-step run needs no error estimate, so
 * this stepper returns the same two classical steps of h (Butcher tableau 0 | 1/2 1/2 |
 * 1/2 0 1/2 | 1 0 0 1 ‖ 1/6 1/3 1/3 1/6) for 8 right-hand sides. Keeping GSL's grid (each
 * call spans two steps; a cycle's shortened last call is split in two halves as GSL splits
 * it) keeps every result equal to GSL's rk4 to rounding, while the rest of GSL's driver
 * machinery is used unchanged. It reports a zero error estimate, so it is only offered for
 * fixed steps (src/ode/integrator.c). */
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_errno.h>

#include "rk4_classic.h"

struct rk4_state {
    double *mid;  /* [dim] the state after the first of the two classical steps */
    double *k[4]; /* [dim] each: the stage derivatives k1 ... k4 of the current step */
    double *arg;  /* [dim] the stage argument */
};

static void rk4_free(void *vstate)
{
    struct rk4_state *s = vstate;
    if (s == NULL)
        return;
    free(s->mid);
    for (int j = 0; j < 4; j++)
        free(s->k[j]);
    free(s->arg);
    free(s);
}

static void *rk4_alloc(size_t dim)
{
    struct rk4_state *s = calloc(1, sizeof *s);
    if (s == NULL)
        return NULL;
    int ok = (s->mid = malloc(dim * sizeof *s->mid)) != NULL;
    ok &= (s->arg = malloc(dim * sizeof *s->arg)) != NULL;
    for (int j = 0; j < 4; j++)
        ok &= (s->k[j] = malloc(dim * sizeof *s->k[j])) != NULL;
    if (!ok) {
        rk4_free(s);
        return NULL;
    }
    return s;
}

/* The stage argument arg = y0 + c k. */
static void stage_argument(size_t dim, const double *restrict y0, double c,
                           const double *restrict k, double *restrict arg)
{
    for (size_t i = 0; i < dim; i++)
        arg[i] = y0[i] + c * k[i];
}

/* y1 = y0 + h/6 (k1 + 2 k2 + 2 k3 + k4), the sum formed left to right. Each stage keeps its
 * own k, so a stage costs one store per component (the argument), not two (the argument and
 * a running sum), and the running sum's order is kept, so the result is the same to the
 * bit. y1 may be y0. */
static void combine(size_t dim, const double y0[], double h, double *const k[4], double y1[])
{
    const double *restrict k1 = k[0], *restrict k2 = k[1], *restrict k3 = k[2];
    const double *restrict k4 = k[3];
    for (size_t i = 0; i < dim; i++)
        y1[i] = y0[i] + h / 6.0 * (((k1[i] + 2.0 * k2[i]) + 2.0 * k3[i]) + k4[i]);
}

/* One classical RK4 step of size h from y0 into y1 (y1 may be y0); y1 is written only when
 * every stage succeeded. */
static int classical_step(struct rk4_state *s, size_t dim, double t, double h, const double y0[],
                          double y1[], const gsl_odeiv2_system *sys)
{
    int status = GSL_ODEIV_FN_EVAL(sys, t, y0, s->k[0]);
    if (status == GSL_SUCCESS) {
        stage_argument(dim, y0, 0.5 * h, s->k[0], s->arg);
        status = GSL_ODEIV_FN_EVAL(sys, t + 0.5 * h, s->arg, s->k[1]);
    }
    if (status == GSL_SUCCESS) {
        stage_argument(dim, y0, 0.5 * h, s->k[1], s->arg);
        status = GSL_ODEIV_FN_EVAL(sys, t + 0.5 * h, s->arg, s->k[2]);
    }
    if (status == GSL_SUCCESS) {
        stage_argument(dim, y0, h, s->k[2], s->arg);
        status = GSL_ODEIV_FN_EVAL(sys, t + h, s->arg, s->k[3]);
    }
    if (status != GSL_SUCCESS)
        return status;
    combine(dim, y0, h, s->k, y1);
    return GSL_SUCCESS;
}

/* Two classical steps of h/2, through s->mid. On failure y is left as it was. */
static int rk4_apply(void *vstate, size_t dim, double t, double h, double y[], double yerr[],
                     const double dydt_in[], double dydt_out[], const gsl_odeiv2_system *sys)
{
    /* can_use_dydt_in = 0 and gives_exact_dydt_out = 0: GSL's evolve passes no dydt_in, and in
     * a fixed step reads no dydt_out (only adaptive control would), so neither is touched:
     * f at the end of the step would cost one more right-hand side per call. */
    (void)dydt_in, (void)dydt_out;
    struct rk4_state *s = vstate;
    int status = classical_step(s, dim, t, 0.5 * h, y, s->mid, sys);
    if (status == GSL_SUCCESS)
        status = classical_step(s, dim, t + 0.5 * h, 0.5 * h, s->mid, y, sys);
    if (status != GSL_SUCCESS)
        return status;
    if (yerr != NULL) /* NULL: integrate.c's direct call, which reads no estimate */
        memset(yerr, 0, dim * sizeof *yerr);
    return GSL_SUCCESS;
}

static int rk4_reset(void *vstate, size_t dim)
{
    (void)vstate, (void)dim;
    return GSL_SUCCESS;
}

static unsigned int rk4_order(void *vstate)
{
    (void)vstate;
    return 4;
}

static int rk4_set_driver(void *vstate, const gsl_odeiv2_driver *d)
{
    (void)vstate, (void)d;
    return GSL_SUCCESS;
}

static const gsl_odeiv2_step_type rk4_classic_type = {"fricreg-rk4", 0,         0,
                                                      rk4_alloc,     rk4_apply, rk4_set_driver,
                                                      rk4_reset,     rk4_order, rk4_free};

const gsl_odeiv2_step_type *fr_step_rk4_classic(void)
{
    return &rk4_classic_type;
}
