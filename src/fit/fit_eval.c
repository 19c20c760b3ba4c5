/* SPDX-License-Identifier: GPL-3.0-or-later */
/* fit_eval.c — the model's backbone for the caller (fricreg_fit_eval) and the fitted one with
 * its band (fricreg_fit_curve), both on modal_iwan.c's levels. */
#include <math.h>
#include <stdlib.h>

#include "fit_internal.h"
#include "modal_iwan.h"
#include "params.h"

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

/* The levels' models into m[n] (allocated here), or the status (recorded). */
static int levels(fricreg_fit *fit, const char *who, const double p[], int kind, size_t n,
                  const double amp[], struct fr_level_model **out)
{
    struct fr_level_model *m = malloc(n * sizeof *m);
    if (m == NULL)
        return fr_fail(fit, FRICREG_ENOMEM, "%s: out of memory for %zu amplitudes", who, n);
    for (size_t i = 0; i < n; i++)
        if (fr_modal_iwan_level(p, kind, fit->sensor, amp[i], fit->brent, &m[i]) != 0) {
            free(m);
            return fr_fail(fit, FRICREG_EINVAL,
                           "%s: amplitude[%zu] = %g is beyond the "
                           "backbone's reach (K0 = 0 with accelerations)",
                           who, i, amp[i]);
        }
    *out = m;
    return FRICREG_OK;
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
    for (int j = 0; j < FR_FIT_NP; j++) {
        if (!isfinite(p[j]))
            return fr_fail(fit, FRICREG_ENONFINITE, "eval: %s is not finite", fr_fit_param_name(j));
        if (!fr_fit_param_in_range(j, p[j]))
            return fr_fail(fit, FRICREG_EINVAL, "eval: %s = %g is out of its range",
                           fr_fit_param_name(j), p[j]);
    }
    struct fr_level_model *m;
    int st = check_amplitudes(fit, "eval", n, amplitude);
    if (st == FRICREG_OK)
        st = levels(fit, "eval", p, kind, n, amplitude, &m);
    if (st != FRICREG_OK)
        return st;
    for (size_t i = 0; i < n; i++) {
        freq_hz[i] = m[i].freq_hz;
        zeta[i] = m[i].zeta;
        if (modal != NULL)
            modal[i] = m[i].modal;
        for (int j = 0; j < FR_FIT_NP; j++) {
            if (dfreq_dp != NULL)
                dfreq_dp[i * FR_FIT_NP + j] = m[i].dfreq[j];
            if (dzeta_dp != NULL)
                dzeta_dp[i * FR_FIT_NP + j] = m[i].dzeta[j];
        }
    }
    free(m);
    return FRICREG_OK;
}

/* g^T C g over the parameters, C the fit's covariance. */
static double variance_along(const double g[], const double cov[])
{
    double v = 0.0;
    for (int i = 0; i < FR_FIT_NP; i++)
        for (int j = 0; j < FR_FIT_NP; j++)
            v += g[i] * cov[i * FR_FIT_NP + j] * g[j];
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
    struct fr_level_model *m;
    int st = check_amplitudes(fit, "curve", n, amplitude);
    if (st == FRICREG_OK)
        st = levels(fit, "curve", fit->result.p, fit->kind, n, amplitude, &m);
    if (st != FRICREG_OK)
        return st;
    for (size_t i = 0; i < n; i++) {
        freq_hz[i] = m[i].freq_hz;
        zeta[i] = m[i].zeta;
        if (sd_freq_hz != NULL) {
            sd_freq_hz[i] = sqrt(variance_along(m[i].dfreq, fit->result.cov));
            sd_zeta[i] = sqrt(variance_along(m[i].dzeta, fit->result.cov));
        }
    }
    free(m);
    return FRICREG_OK;
}
