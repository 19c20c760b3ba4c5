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
 * fixed steps (src/integrator.c). */
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_errno.h>

#include "integrator.h"

struct rk4_state {
    double *y0;  /* [dim] the state at the start of the current classical step */
    double *k;   /* [dim] the current stage derivative */
    double *sum; /* [dim] k1 + 2 k2 + 2 k3 + k4, accumulated */
    double *y1;  /* [dim] the stage argument */
};

static void rk4_free(void *vstate)
{
    struct rk4_state *s = vstate;
    if (s == NULL)
        return;
    free(s->y0);
    free(s->k);
    free(s->sum);
    free(s->y1);
    free(s);
}

static void *rk4_alloc(size_t dim)
{
    struct rk4_state *s = calloc(1, sizeof *s);
    if (s == NULL)
        return NULL;
    s->y0 = malloc(dim * sizeof *s->y0);
    s->k = malloc(dim * sizeof *s->k);
    s->sum = malloc(dim * sizeof *s->sum);
    s->y1 = malloc(dim * sizeof *s->y1);
    if (!s->y0 || !s->k || !s->sum || !s->y1) {
        rk4_free(s);
        return NULL;
    }
    return s;
}

/* y1 = y0 + c k, and sum += w k. */
static void stage_update(struct rk4_state *s, size_t dim, double c, double w)
{
    for (size_t i = 0; i < dim; i++) {
        s->y1[i] = s->y0[i] + c * s->k[i];
        s->sum[i] += w * s->k[i];
    }
}

/* One classical RK4 step of size h from s->y0 into y. */
static int classical_step(struct rk4_state *s, size_t dim, double t, double h, double y[],
                          const gsl_odeiv2_system *sys)
{
    memset(s->sum, 0, dim * sizeof *s->sum);
    int status = GSL_ODEIV_FN_EVAL(sys, t, s->y0, s->k); /* k1 */
    if (status == GSL_SUCCESS) {
        stage_update(s, dim, 0.5 * h, 1.0);
        status = GSL_ODEIV_FN_EVAL(sys, t + 0.5 * h, s->y1, s->k); /* k2 */
    }
    if (status == GSL_SUCCESS) {
        stage_update(s, dim, 0.5 * h, 2.0);
        status = GSL_ODEIV_FN_EVAL(sys, t + 0.5 * h, s->y1, s->k); /* k3 */
    }
    if (status == GSL_SUCCESS) {
        stage_update(s, dim, h, 2.0);
        status = GSL_ODEIV_FN_EVAL(sys, t + h, s->y1, s->k); /* k4 */
    }
    if (status != GSL_SUCCESS)
        return status;
    for (size_t i = 0; i < dim; i++)
        y[i] = s->y0[i] + h / 6.0 * (s->sum[i] + s->k[i]);
    return GSL_SUCCESS;
}

/* Two classical steps of h/2. On failure y is left as it was: GSL's evolve restores it. */
static int rk4_apply(void *vstate, size_t dim, double t, double h, double y[], double yerr[],
                     const double dydt_in[], double dydt_out[], const gsl_odeiv2_system *sys)
{
    /* can_use_dydt_in = 0 and gives_exact_dydt_out = 0: GSL's evolve passes no dydt_in, and in
     * a fixed step reads no dydt_out (only adaptive control would), so neither is touched:
     * f at the end of the step would cost one more right-hand side per call. */
    (void)dydt_in, (void)dydt_out;
    struct rk4_state *s = vstate;
    memcpy(s->y0, y, dim * sizeof *y);
    int status = classical_step(s, dim, t, 0.5 * h, s->y0, sys);
    if (status == GSL_SUCCESS)
        status = classical_step(s, dim, t + 0.5 * h, 0.5 * h, y, sys);
    if (status != GSL_SUCCESS)
        return status;
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
