/* SPDX-License-Identifier: GPL-3.0-or-later */
/* step_control.c — the error control of fricreg's adaptive GSL runs (step_control.h): GSL's
 * standard control with a level per component, on fricreg's memory, and for explicit steppers
 * no growth of the step after a rejected one. */
#include <math.h>
#include <stdlib.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_machine.h>

#include "step_control.h"
#include "base/free_all.h"

#define SAFETY 0.9    /* GSL's S: the step aimed at 0.9 of the one the estimate allows */
#define REJECT 1.1    /* a step is rejected above 1.1 of the level ... */
#define GROW 0.5      /* ... and the next one grown below 0.5 of it */
#define MAX_CHANGE 5. /* by at most 5x either way */

struct step_control {
    double eps_rel;
    size_t dim;
    double *levels;        /* [2 dim]: atol_i, then the weight w_i of eps_rel in component i */
    int hold_after_reject; /* the step after a rejected one does not grow */
    int after_reject;      /* the last step the control judged was rejected */
};

static void *control_alloc(void)
{
    return calloc(1, sizeof(struct step_control));
}

static int control_init(void *vstate, double eps_abs, double eps_rel, double a_y, double a_dydt)
{
    (void)eps_abs, (void)a_y, (void)a_dydt; /* atol per component; a_y = 1, a_dydt = 0 */
    ((struct step_control *)vstate)->eps_rel = eps_rel;
    return GSL_SUCCESS;
}

/* max_i |yerr_i| / D0_i, D0_i = atol_i + w_i eps_rel |y_i|; a component whose level is 0
 * counts as GSL's does: infinite if it has an error, ignored if it has none (0/0). */
static double error_ratio(const struct step_control *c, size_t dim, const double y[],
                          const double yerr[])
{
    double rmax = GSL_DBL_MIN;
    for (size_t i = 0; i < dim && i < c->dim; i++)
        rmax = fmax(rmax, fabs(yerr[i]) /
                              (c->levels[i] + c->levels[c->dim + i] * c->eps_rel * fabs(y[i])));
    return rmax;
}

static int control_hadjust(void *vstate, size_t dim, unsigned int ord, const double y[],
                           const double yerr[], const double yp[], double *h)
{
    struct step_control *c = vstate;
    const double r = error_ratio(c, dim, y, yerr), h_old = *h;
    const int after_reject = c->after_reject;
    (void)yp;
    c->after_reject = r > REJECT;
    if (r > REJECT) {
        *h = h_old * fmax(SAFETY / pow(r, 1.0 / ord), 1.0 / MAX_CHANGE);
        return GSL_ODEIV_HADJ_DEC;
    }
    if (r < GROW && !(c->hold_after_reject && after_reject)) {
        *h = h_old * fmax(fmin(SAFETY / pow(r, 1.0 / (ord + 1.0)), MAX_CHANGE), 1.0);
        return GSL_ODEIV_HADJ_INC;
    }
    return GSL_ODEIV_HADJ_NIL;
}

/* The level the implicit and multistep steppers iterate to. */
static int control_errlevel(void *vstate, const double y, const double dydt, const double h,
                            const size_t ind, double *errlev)
{
    const struct step_control *c = vstate;
    (void)dydt, (void)h;
    size_t i = ind < c->dim ? ind : c->dim - 1;
    *errlev = c->levels[i] + c->levels[c->dim + i] * c->eps_rel * fabs(y);
    return GSL_SUCCESS;
}

static int control_set_driver(void *vstate, const gsl_odeiv2_driver *d)
{
    (void)vstate, (void)d;
    return GSL_SUCCESS;
}

static void control_free(void *vstate)
{
    struct step_control *c = vstate;
    if (c != NULL)
        free(c->levels);
    free(c);
}

static const gsl_odeiv2_control_type control_type = {"fricreg",        control_alloc,
                                                     control_init,     control_hadjust,
                                                     control_errlevel, control_set_driver,
                                                     control_free};

gsl_odeiv2_control *fr_step_control_new(size_t dim, const double atol[], double epsabs,
                                        const double rel_weight[], double epsrel,
                                        int hold_after_reject)
{
    gsl_odeiv2_control *c = malloc(sizeof *c);
    struct step_control *state = control_alloc();
    double *levels = malloc(2 * dim * sizeof *levels);
    if (c == NULL || state == NULL || levels == NULL) {
        FR_FREE_ALL(c, state, levels);
        return NULL;
    }
    for (size_t i = 0; i < dim; i++) {
        levels[i] = atol ? atol[i] : epsabs;
        levels[dim + i] = rel_weight ? rel_weight[i] : 1.0;
    }
    *state = (struct step_control){.eps_rel = epsrel,
                                   .dim = dim,
                                   .levels = levels,
                                   .hold_after_reject = hold_after_reject};
    *c = (gsl_odeiv2_control){.type = &control_type, .state = state};
    return c;
}
