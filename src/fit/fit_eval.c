/* SPDX-License-Identifier: GPL-3.0-or-later */
/* fit_eval.c — the model's backbone for the caller (fricreg_fit_eval) and the fitted one with
 * its band (fricreg_fit_curve), both on the model's levels (model.h). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "model.h"

/* FRICREG_OK if amplitude[n] are all finite and > 0, else the status (recorded). */
static int check_amplitudes(fricreg_fit *fit, const char *who, size_t n, const double amp[])
{
    if (n == 0)
        return fr_fail(fit, FRICREG_EINVAL, "%s: n = 0 amplitudes", who);
    for (size_t i = 0; i < n; i++) {
        if (!isfinite(amp[i]))
            return fr_fail(fit, FRICREG_ENONFINITE, "%s: amplitude[%zu] is not finite", who, i);
        if (!(amp[i] > 0.0))
            return fr_fail(fit, FRICREG_EINVAL, "%s: amplitude[%zu] = %g is not > 0", who, i,
                           amp[i]);
    }
    return FRICREG_OK;
}

/* The model at p at amp[n] of kind into *m (its block in *block, freed by the caller), or the
 * status (recorded). */
static int levels(fricreg_fit *fit, const char *who, const double p[], int kind, size_t n,
                  const double amp[], struct fr_fit_levels *m, double **block)
{
    double *guess;
    *block = fr_fit_levels_alloc(n, fit->np, m, &guess);
    if (*block == NULL)
        return fr_fail(fit, FRICREG_ENOMEM, "%s: out of memory for %zu amplitudes", who, n);
    size_t bad = FR_FIT_REACHED;
    int st = fit->model->eval(fit, p, kind, n, amp, guess, m, &bad);
    if (st == FRICREG_OK)
        return st;
    free(*block);
    if (bad != FR_FIT_REACHED)
        return fr_fail(fit, st, "%s: amplitude[%zu] = %g is beyond the backbone's reach (%s)", who,
                       bad, amp[bad], fit->reason);
    return fr_fail(fit, st, "%s: the model cannot be evaluated: %s", who, fit->reason);
}

int fricreg_fit_eval(fricreg_fit *fit, const double p[], int kind, size_t n,
                     const double amplitude[], double freq_hz[], double zeta[], double modal[],
                     double dfreq_dp[], double dzeta_dp[])
{
    if (fit == NULL)
        return FRICREG_ENULL;
    if (p == NULL || amplitude == NULL || freq_hz == NULL || zeta == NULL)
        return fr_fail(fit, FRICREG_ENULL, "eval: p, amplitude, freq_hz or zeta is NULL");
    if (kind < FRICREG_FIT_DISPLACEMENT || kind > FRICREG_FIT_ACCELERATION)
        return fr_fail(fit, FRICREG_EINVAL, "eval: unknown amplitude kind %d", kind);
    size_t np = fit->np;
    for (size_t j = 0; j < np; j++) {
        const char *name = fit->model->name(fit, (int)j);
        if (!isfinite(p[j]))
            return fr_fail(fit, FRICREG_ENONFINITE, "eval: %s is not finite", name);
        if (!fit->model->in_range((int)j, p[j]))
            return fr_fail(fit, FRICREG_EINVAL, "eval: %s = %g is out of its range", name, p[j]);
    }
    struct fr_fit_levels m;
    double *block;
    int st = check_amplitudes(fit, "eval", n, amplitude);
    if (st == FRICREG_OK)
        st = levels(fit, "eval", p, kind, n, amplitude, &m, &block);
    if (st != FRICREG_OK)
        return st;
    for (size_t i = 0; i < n; i++) {
        freq_hz[i] = m.freq_hz[i];
        zeta[i] = m.zeta[i];
        if (modal != NULL)
            modal[i] = m.modal[i];
    }
    if (dfreq_dp != NULL)
        memcpy(dfreq_dp, m.dfreq, n * np * sizeof *dfreq_dp);
    if (dzeta_dp != NULL)
        memcpy(dzeta_dp, m.dzeta, n * np * sizeof *dzeta_dp);
    free(block);
    return FRICREG_OK;
}

/* g^T C g over the np parameters, C the fit's covariance. */
static double variance_along(size_t np, const double g[], const double cov[])
{
    double v = 0.0;
    for (size_t i = 0; i < np; i++)
        for (size_t j = 0; j < np; j++)
            v += g[i] * cov[i * np + j] * g[j];
    return v > 0.0 ? v : 0.0;
}

int fricreg_fit_curve(fricreg_fit *fit, size_t n, const double amplitude[], double freq_hz[],
                      double zeta[], double sd_freq_hz[], double sd_zeta[])
{
    if (fit == NULL)
        return FRICREG_ENULL;
    if (amplitude == NULL || freq_hz == NULL || zeta == NULL)
        return fr_fail(fit, FRICREG_ENULL, "curve: amplitude, freq_hz or zeta is NULL");
    if ((sd_freq_hz == NULL) != (sd_zeta == NULL))
        return fr_fail(fit, FRICREG_ENULL, "curve: only one of sd_freq_hz, sd_zeta is NULL");
    if (!fit->have_fit)
        return fr_fail(fit, FRICREG_EINVAL,
                       "curve: no fit (no run has succeeded since the "
                       "last setter)");
    struct fr_fit_levels m;
    double *block;
    size_t np = fit->np;
    int st = check_amplitudes(fit, "curve", n, amplitude);
    if (st == FRICREG_OK)
        st = levels(fit, "curve", fit->result.p, fit->kind, n, amplitude, &m, &block);
    if (st != FRICREG_OK)
        return st;
    for (size_t i = 0; i < n; i++) {
        freq_hz[i] = m.freq_hz[i];
        zeta[i] = m.zeta[i];
        if (sd_freq_hz != NULL) {
            sd_freq_hz[i] = sqrt(variance_along(np, m.dfreq + i * np, fit->result.cov));
            sd_zeta[i] = sqrt(variance_along(np, m.dzeta + i * np, fit->result.cov));
        }
    }
    free(block);
    return FRICREG_OK;
}
