/* SPDX-License-Identifier: GPL-3.0-or-later */
/* fit.c — a fit's life cycle and setters (fricreg_fit.h): each setter checks every input
 * before it changes anything, and forgets the last run's result. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/gsl_mem.h"
#include "hb_model.h"

#define MAX_LEVELS 1000000
#define MAX_STARTS 1000
#define LEVEL_ARRAYS 7 /* amp, freq, zeta, sd_freq, sd_zeta, res_freq, res_zeta */

FR_ERROR_GETTERS(fricreg_fit, "NULL fit")

int fricreg_fit_create(fricreg_fit **out)
{
    if (out == NULL)
        return FRICREG_ENULL;
    fricreg_fit *fit = calloc(1, sizeof *fit);
    gsl_root_fsolver *brent = fr_gsl_brent_new();
    if (fit == NULL || brent == NULL) {
        free(fit);
        free(brent);
        return FRICREG_ENOMEM;
    }
    fit->brent = brent;
    fit->kind = FRICREG_FIT_DISPLACEMENT;
    fit->sensor = 1.0;
    fr_fit_use_modal_iwan(fit);
    *out = fit;
    return FRICREG_OK;
}

void fricreg_fit_free(fricreg_fit *fit)
{
    if (fit == NULL)
        return;
    free(fit->amp);
    free(fit->brent);
    fr_fit_hb_free(fit->hb);
    free(fit);
}

/* Every value of x[n] finite and > 0, else the status (the message names what and where). */
static int check_positive(fricreg_fit *fit, const char *who, const char *what, size_t n,
                          const double x[])
{
    for (size_t i = 0; i < n; i++) {
        if (!isfinite(x[i]))
            return fr_fail(fit, FRICREG_ENONFINITE, "%s: %s[%zu] is not finite", who, what, i);
        if (!(x[i] > 0.0))
            return fr_fail(fit, FRICREG_EINVAL, "%s: %s[%zu] = %g is not > 0", who, what, i, x[i]);
    }
    return FRICREG_OK;
}

int fricreg_fit_set_levels(fricreg_fit *fit, size_t n, int kind, const double amplitude[],
                           const double freq_hz[], const double zeta[])
{
    if (fit == NULL)
        return FRICREG_ENULL;
    if (amplitude == NULL || freq_hz == NULL || zeta == NULL)
        return fr_fail(fit, FRICREG_ENULL, "set_levels: amplitude, freq_hz or zeta is NULL");
    if (n == 0 || n > MAX_LEVELS)
        return fr_fail(fit, FRICREG_EINVAL, "set_levels: n = %zu levels, not 1..%d", n, MAX_LEVELS);
    if (kind < FRICREG_FIT_DISPLACEMENT || kind > FRICREG_FIT_ACCELERATION)
        return fr_fail(fit, FRICREG_EINVAL, "set_levels: unknown amplitude kind %d", kind);
    int st = check_positive(fit, "set_levels", "amplitude", n, amplitude);
    if (st == FRICREG_OK)
        st = check_positive(fit, "set_levels", "freq_hz", n, freq_hz);
    if (st == FRICREG_OK)
        st = check_positive(fit, "set_levels", "zeta", n, zeta);
    if (st != FRICREG_OK)
        return st;
    double *block = malloc(LEVEL_ARRAYS * n * sizeof *block);
    if (block == NULL)
        return fr_fail(fit, FRICREG_ENOMEM, "set_levels: out of memory for %zu levels", n);
    free(fit->amp);
    double *arrays[LEVEL_ARRAYS];
    for (int k = 0; k < LEVEL_ARRAYS; k++)
        arrays[k] = block + (size_t)k * n;
    fit->amp = arrays[0];
    fit->freq = arrays[1];
    fit->zeta = arrays[2];
    fit->sd_freq = arrays[3];
    fit->sd_zeta = arrays[4];
    fit->res_freq = arrays[5];
    fit->res_zeta = arrays[6];
    memcpy(fit->amp, amplitude, n * sizeof *amplitude);
    memcpy(fit->freq, freq_hz, n * sizeof *freq_hz);
    memcpy(fit->zeta, zeta, n * sizeof *zeta);
    fit->n = n;
    fit->kind = kind;
    fit->has_sd = 0;
    fit->have_fit = 0;
    return FRICREG_OK;
}

int fricreg_fit_set_deviations(fricreg_fit *fit, size_t n, const double sd_freq_hz[],
                               const double sd_zeta[])
{
    if (fit == NULL)
        return FRICREG_ENULL;
    if ((sd_freq_hz == NULL) != (sd_zeta == NULL))
        return fr_fail(fit, FRICREG_ENULL,
                       "set_deviations: only one of sd_freq_hz, sd_zeta "
                       "is NULL");
    if (n != fit->n)
        return fr_fail(fit, FRICREG_ESIZE, "set_deviations: n = %zu, but %zu levels are set", n,
                       fit->n);
    if (sd_freq_hz != NULL) {
        int st = check_positive(fit, "set_deviations", "sd_freq_hz", n, sd_freq_hz);
        if (st == FRICREG_OK)
            st = check_positive(fit, "set_deviations", "sd_zeta", n, sd_zeta);
        if (st != FRICREG_OK)
            return st;
        memcpy(fit->sd_freq, sd_freq_hz, n * sizeof *sd_freq_hz);
        memcpy(fit->sd_zeta, sd_zeta, n * sizeof *sd_zeta);
    }
    fit->has_sd = sd_freq_hz != NULL;
    fit->have_fit = 0;
    return FRICREG_OK;
}

int fricreg_fit_set_sensor(fricreg_fit *fit, double s)
{
    if (fit == NULL)
        return FRICREG_ENULL;
    if (!isfinite(s))
        return fr_fail(fit, FRICREG_ENONFINITE, "set_sensor: s is not finite");
    if (s == 0.0)
        return fr_fail(fit, FRICREG_EINVAL, "set_sensor: s = 0 (the sensor sees no mode)");
    fit->sensor = s;
    if (fit->hb != NULL) /* the HB model's levels modal again */
        fit->hb->has_dof = 0;
    fit->have_fit = 0;
    return FRICREG_OK;
}

static int check_which(fricreg_fit *fit, const char *who, int which)
{
    if (which < 0 || (size_t)which >= fit->np)
        return fr_fail(fit, FRICREG_EINVAL, "%s: unknown parameter %d (the model has %zu)", who,
                       which, fit->np);
    return FRICREG_OK;
}

int fricreg_fit_set_free(fricreg_fit *fit, int which, double start, double lower, double upper)
{
    if (fit == NULL)
        return FRICREG_ENULL;
    int st = check_which(fit, "set_free", which);
    if (st != FRICREG_OK)
        return st;
    const char *name = fit->model->name(fit, which);
    double floor = fit->model->floor(which);
    if (isnan(lower) || isnan(upper))
        return fr_fail(fit, FRICREG_ENONFINITE, "set_free: a bound of %s is NaN", name);
    if (lower < floor || !(upper > lower))
        return fr_fail(fit, FRICREG_EINVAL,
                       "set_free: bounds [%g, %g] of %s: lower must be "
                       ">= %g and upper > lower",
                       lower, upper, name, floor);
    if (!isnan(start) && !(start > lower && start < upper && isfinite(start)))
        return fr_fail(fit, FRICREG_EINVAL, "set_free: start %g of %s is not inside (%g, %g)",
                       start, name, lower, upper);
    fit->par[which] = (struct fr_fit_param){1, start, lower, upper};
    fit->have_fit = 0;
    return FRICREG_OK;
}

int fricreg_fit_set_fixed(fricreg_fit *fit, int which, double value)
{
    if (fit == NULL)
        return FRICREG_ENULL;
    int st = check_which(fit, "set_fixed", which);
    if (st != FRICREG_OK)
        return st;
    const char *name = fit->model->name(fit, which);
    if (!isfinite(value))
        return fr_fail(fit, FRICREG_ENONFINITE, "set_fixed: %s is not finite", name);
    if (!fit->model->in_range(which, value))
        return fr_fail(fit, FRICREG_EINVAL, "set_fixed: %s = %g is out of its range", name, value);
    fit->par[which] = (struct fr_fit_param){0, value, fit->model->floor(which), INFINITY};
    fit->have_fit = 0;
    return FRICREG_OK;
}

int fricreg_fit_set_starts(fricreg_fit *fit, size_t nstarts)
{
    if (fit == NULL)
        return FRICREG_ENULL;
    if (nstarts == 0 || nstarts > MAX_STARTS)
        return fr_fail(fit, FRICREG_EINVAL, "set_starts: %zu starts, not 1..%d", nstarts,
                       MAX_STARTS);
    fit->nstarts = nstarts;
    fit->have_fit = 0;
    return FRICREG_OK;
}
