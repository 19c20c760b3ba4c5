/* SPDX-License-Identifier: GPL-3.0-or-later */
/* ode_driver.c — gsl_odeiv2_driver_alloc_y_new, with every allocation checked (ode_driver.h):
 * fricreg's own, except the stepper's private state, which only GSL can allocate; and a fixed
 * step that fails where the stepper says so only in its error estimate (bsimp). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_machine.h>

#include "ode_driver.h"

/* The type behind gsl_odeiv2_control_y_new: a data symbol libgsl exports (since GSL 1.14) but
 * gsl_odeiv2.h does not declare. */
extern const gsl_odeiv2_control_type *gsl_odeiv2_control_standard;

/* The standard control's private state (ode-initval2/cstd.c, GSL 1.14 to 2.7): eps_abs,
 * eps_rel, a_y, a_dydt. Allocated here with room to spare, so that only the stepper's own
 * state is left to GSL's allocator. */
#define CONTROL_STATE_DOUBLES 16

static gsl_odeiv2_control *control_y_new(double epsabs, double epsrel)
{
    gsl_odeiv2_control *c = malloc(sizeof *c);
    void *state = calloc(CONTROL_STATE_DOUBLES, sizeof(double));
    if (c == NULL || state == NULL) {
        free(c);
        free(state);
        return NULL;
    }
    *c = (gsl_odeiv2_control){.type = gsl_odeiv2_control_standard, .state = state};
    gsl_odeiv2_control_init(c, epsabs, epsrel, 1.0, 0.0); /* the caller checked both >= 0 */
    return c;
}

/* gsl_odeiv2_evolve_alloc's five allocations, checked; gsl_odeiv2_evolve_free frees them. */
static gsl_odeiv2_evolve *evolve_new(size_t dim)
{
    gsl_odeiv2_evolve *e = calloc(1, sizeof *e);
    if (e == NULL)
        return NULL;
    e->dimension = dim;
    e->y0 = malloc(dim * sizeof(double));
    e->yerr = malloc(dim * sizeof(double));
    e->dydt_in = malloc(dim * sizeof(double));
    e->dydt_out = malloc(dim * sizeof(double));
    if (!e->y0 || !e->yerr || !e->dydt_in || !e->dydt_out) {
        gsl_odeiv2_evolve_free(e);
        return NULL;
    }
    return e;
}

/* ---- The per-component control (fr_ode_driver_alloc_vector) ----------------------------
 * GSL's standard control (ode-initval2/cstd.c, GSL 1.14 to 2.7) with a_y = 1, a_dydt = 0 and
 * the absolute level per component: D0_i = atol_i + eps_rel |y_i|; the step is cut when
 * max_i |yerr_i|/D0_i > 1.1 (by S/r^(1/q), S = 0.9, at most 5x) and grown when it is below
 * 0.5 (by S/r^(1/(q+1)), at most 5x, never shrunk), the same heuristic as GSL's. */
struct vector_control {
    double eps_rel;
    size_t dim;
    double *atol; /* [2 dim]: atol_i, then the weight w_i of eps_rel in component i */
};

static void *vector_alloc(void)
{
    return calloc(1, sizeof(struct vector_control));
}

static int vector_init(void *vstate, double eps_abs, double eps_rel, double a_y, double a_dydt)
{
    (void)eps_abs, (void)a_y, (void)a_dydt; /* atol per component; a_y = 1, a_dydt = 0 */
    ((struct vector_control *)vstate)->eps_rel = eps_rel;
    return GSL_SUCCESS;
}

static int vector_hadjust(void *vstate, size_t dim, unsigned int ord, const double y[],
                          const double yerr[], const double yp[], double *h)
{
    const struct vector_control *c = vstate;
    const double S = 0.9, h_old = *h;
    double rmax = GSL_DBL_MIN;
    (void)yp;
    for (size_t i = 0; i < dim && i < c->dim; i++)
        rmax = fmax(rmax,
                    fabs(yerr[i]) / (c->atol[i] + c->atol[c->dim + i] * c->eps_rel * fabs(y[i])));
    if (rmax > 1.1) {
        *h = h_old * fmax(S / pow(rmax, 1.0 / ord), 0.2);
        return GSL_ODEIV_HADJ_DEC;
    }
    if (rmax < 0.5) {
        *h = h_old * fmax(fmin(S / pow(rmax, 1.0 / (ord + 1.0)), 5.0), 1.0);
        return GSL_ODEIV_HADJ_INC;
    }
    return GSL_ODEIV_HADJ_NIL;
}

/* The level the implicit and multistep steppers iterate to: > 0, as every atol_i is. */
static int vector_errlevel(void *vstate, const double y, const double dydt, const double h,
                           const size_t ind, double *errlev)
{
    const struct vector_control *c = vstate;
    (void)dydt, (void)h;
    size_t i = ind < c->dim ? ind : c->dim - 1;
    *errlev = c->atol[i] + c->atol[c->dim + i] * c->eps_rel * fabs(y);
    return GSL_SUCCESS;
}

static int vector_set_driver(void *vstate, const gsl_odeiv2_driver *d)
{
    (void)vstate, (void)d;
    return GSL_SUCCESS;
}

static void vector_free(void *vstate)
{
    struct vector_control *c = vstate;
    if (c != NULL)
        free(c->atol);
    free(c);
}

static const gsl_odeiv2_control_type vector_type = {
    "fricreg per-component", vector_alloc,      vector_init, vector_hadjust,
    vector_errlevel,         vector_set_driver, vector_free};

static gsl_odeiv2_control *control_vector_new(const double atol[], const double rel_weight[],
                                              size_t dim, double epsrel)
{
    gsl_odeiv2_control *c = malloc(sizeof *c);
    struct vector_control *state = vector_alloc();
    double *copy = malloc(2 * dim * sizeof *copy);
    if (c == NULL || state == NULL || copy == NULL) {
        free(c);
        free(state);
        free(copy);
        return NULL;
    }
    memcpy(copy, atol, dim * sizeof *copy);
    for (size_t i = 0; i < dim; i++)
        copy[dim + i] = rel_weight ? rel_weight[i] : 1.0;
    *state = (struct vector_control){.eps_rel = epsrel, .dim = dim, .atol = copy};
    *c = (gsl_odeiv2_control){.type = &vector_type, .state = state};
    return c;
}

/* The driver around a stepper of T and the control c (NULL: the allocation failed). */
static gsl_odeiv2_driver *driver_with(const gsl_odeiv2_system *sys, const gsl_odeiv2_step_type *T,
                                      double hstart, double epsabs, double epsrel,
                                      const double atol[], const double rel_weight[])
{
    gsl_odeiv2_driver *d = calloc(1, sizeof *d);
    if (d == NULL)
        return NULL;
    d->sys = sys;
    d->s = gsl_odeiv2_step_alloc(T, sys->dimension);
    d->e = d->s ? evolve_new(sys->dimension) : NULL;
    if (d->e != NULL)
        d->c = atol ? control_vector_new(atol, rel_weight, sys->dimension, epsrel)
                    : control_y_new(epsabs, epsrel);
    if (d->c != NULL) {
        d->h = hstart;
        d->hmin = 0.0;
        d->hmax = GSL_DBL_MAX;
        gsl_odeiv2_step_set_driver(d->s, d);
        gsl_odeiv2_evolve_set_driver(d->e, d);
        gsl_odeiv2_control_set_driver(d->c, d);
    }
    if (d->c == NULL) {
        gsl_odeiv2_driver_free(d); /* frees the parts that exist */
        return NULL;
    }
    return d;
}

gsl_odeiv2_driver *fr_ode_driver_alloc(const gsl_odeiv2_system *sys, const gsl_odeiv2_step_type *T,
                                       double hstart, double epsabs, double epsrel)
{
    return driver_with(sys, T, hstart, epsabs, epsrel, NULL, NULL);
}

gsl_odeiv2_driver *fr_ode_driver_alloc_vector(const gsl_odeiv2_system *sys,
                                              const gsl_odeiv2_step_type *T, double hstart,
                                              const double atol[], const double rel_weight[],
                                              double epsrel)
{
    return driver_with(sys, T, hstart, 0.0, epsrel, atol, rel_weight);
}

int fr_ode_apply_fixed_step(gsl_odeiv2_driver *d, double *t, double h, double y[])
{
    double t0 = *t;
    size_t dim = d->sys->dimension;
    int status = gsl_odeiv2_evolve_apply_fixed_step(d->e, NULL, d->s, d->sys, t, h, y);
    for (size_t k = 0; status == GSL_SUCCESS && k < dim; k++)
        if (isfinite(y[k]) && !isfinite(d->e->yerr[k])) {
            memcpy(y, d->e->y0, dim * sizeof *y); /* the step's start, as GSL keeps it */
            *t = t0;
            status = GSL_FAILURE;
        }
    return status;
}
