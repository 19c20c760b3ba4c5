/* SPDX-License-Identifier: GPL-3.0-or-later */
/* hb_model.c — a harmonic-balance driver's nonlinear mode, or its quasi-static modal analysis,
 * as the fit's model (model.h): its parameters' names and ranges, its first start (each element
 * parameter the driver's value at fricreg_fit_set_model_hb or _qsma; Rayleigh's coefficients,
 * which the driver does not report, from the levels), and the driver's values set to a
 * parameter vector before each backbone (EPMC's, hb_levels.c, or QSMA's, qsma_levels.c). */
#include <math.h>
#include <stdio.h>

#include "base/fr_math.h"
#include "hb_levels.h"
#include "qsma_levels.h"
#include "hb_model.h"

static const char *name(const fricreg_fit *fit, int j)
{
    return fit->hb->names[j];
}

static double floor0(int j)
{
    (void)j;
    return 0.0;
}

/* Every parameter (a stiffness, a slip force, a damping coefficient) is >= 0; the driver
 * checks the rest when it is set (a stiffness > 0). */
static int in_range(int j, double v)
{
    (void)j;
    return isfinite(v) && v >= 0.0;
}

/* Index of the smallest amplitude level. */
static size_t lowest(const fricreg_fit *fit)
{
    size_t lo = 0;
    for (size_t i = 1; i < fit->n; i++)
        if (fit->amp[i] < fit->amp[lo])
            lo = i;
    return lo;
}

/* Rayleigh's start: half the linear damping xi = 2 omega zeta of the smallest level (the joint
 * adds the rest), split evenly between a0 and a1 omega^2 where both are parameters. */
static void start(const fricreg_fit *fit, double p[])
{
    const struct fr_fit_hb *m = fit->hb;
    size_t lo = lowest(fit), ndamp = 0;
    double w = FR_TWO_PI * fit->freq[lo], xi = w * fit->zeta[lo];
    for (size_t j = 0; j < fit->np; j++)
        ndamp += m->kind[j] == FRICREG_HB_NMA_PARAM_DAMPING;
    for (size_t j = 0; j < fit->np; j++) {
        p[j] = m->value0[j];
        if (m->kind[j] == FRICREG_HB_NMA_PARAM_DAMPING)
            p[j] = xi / (double)ndamp / (m->index[j] == 1 ? 1.0 : w * w);
    }
}

int fr_fit_hb_apply(fricreg_fit *fit, const double p[])
{
    const struct fr_fit_hb *m = fit->hb;
    double rayleigh[3] = {0.0, 0.0, 0.0};
    int damped = 0, st = FRICREG_OK;
    for (size_t j = 0; j < fit->np && st == FRICREG_OK; j++) {
        if (m->kind[j] == FRICREG_HB_NMA_PARAM_DAMPING) {
            rayleigh[m->index[j]] = p[j];
            damped = 1;
        } else {
            st = fricreg_hb_set_element_param(m->hb, m->first[j], m->count[j], m->index[j], p[j]);
        }
    }
    if (st == FRICREG_OK && damped)
        st = fricreg_hb_set_rayleigh(m->hb, rayleigh[1], rayleigh[2]);
    if (st != FRICREG_OK)
        snprintf(fit->reason, sizeof fit->reason, "%s", fricreg_hb_errmsg(m->hb));
    return st;
}

void fr_fit_hb_save(fricreg_fit *fit, double v[])
{
    const struct fr_fit_hb *m = fit->hb;
    for (size_t j = 0; j < fit->np; j++)
        if (m->kind[j] != FRICREG_HB_NMA_PARAM_ELEMENT ||
            fricreg_hb_get_element_param(m->hb, m->first[j], m->index[j], &v[j]) != FRICREG_OK)
            v[j] = NAN;
}

void fr_fit_hb_restore(fricreg_fit *fit, const double v[])
{
    const struct fr_fit_hb *m = fit->hb;
    for (size_t j = 0; j < fit->np; j++)
        if (!isnan(v[j])) /* the value was the driver's: it takes it again */
            (void)fricreg_hb_set_element_param(m->hb, m->first[j], m->count[j], m->index[j], v[j]);
}

static int eval(fricreg_fit *fit, const double p[], int kind, size_t n, const double amp[],
                double guess[], const struct fr_fit_levels *out, size_t *bad)
{
    *bad = FR_FIT_REACHED;
    int st = fr_fit_hb_apply(fit, p);
    return st == FRICREG_OK ? fr_fit_hb_levels(fit, kind, n, amp, guess, out, bad) : st;
}

static int eval_qsma(fricreg_fit *fit, const double p[], int kind, size_t n, const double amp[],
                     double guess[], const struct fr_fit_levels *out, size_t *bad)
{
    *bad = FR_FIT_REACHED;
    int st = fr_fit_hb_apply(fit, p);
    return st == FRICREG_OK ? fr_fit_qsma_levels(fit, kind, n, amp, guess, out, bad) : st;
}

const struct fr_fit_model fr_fit_hb_model = {name, floor0, in_range, start, eval};
const struct fr_fit_model fr_fit_qsma_model = {name, floor0, in_range, start, eval_qsma};
