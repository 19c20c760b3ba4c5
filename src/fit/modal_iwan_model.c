/* SPDX-License-Identifier: GPL-3.0-or-later */
/* modal_iwan_model.c — the modal Iwan model as the fit's model (model.h): the closed forms of
 * modal_iwan.c at each level, its parameters' names and ranges (params.c), and its first start
 * made from the levels, read as the model would make them:
 *   K0 + K_T = omega^2 at the smallest amplitude (the joint stuck);
 *   K_T = 2 (omega_lo^2 - omega_hi^2), within 0.1 .. 0.9 of it (the joint's share of the drop);
 *   F_S = K_T a_max, a_max the largest level's modal amplitude (macroslip near the top level);
 *   zeta0 = half the smallest measured zeta; chi + 1 = the slope of log(zeta - zeta0) against
 *   log a between the smallest and largest levels (D/(k a^2) ~ a^(chi+1) below macroslip),
 *   within -0.9 .. 3; beta = 1. */
#include <math.h>
#include <stdio.h>

#include "base/fr_math.h"
#include "modal_iwan.h"
#include "model.h"
#include "params.h"

static double clamp(double v, double lo, double hi)
{
    return v < lo ? lo : v > hi ? hi : v;
}

/* Indices of the smallest and largest amplitude levels. */
static void extremes(const fricreg_fit *fit, size_t *lo, size_t *hi)
{
    *lo = *hi = 0;
    for (size_t i = 1; i < fit->n; i++) {
        if (fit->amp[i] < fit->amp[*lo])
            *lo = i;
        if (fit->amp[i] > fit->amp[*hi])
            *hi = i;
    }
}

static void from_levels(const fricreg_fit *fit, double p[])
{
    size_t lo, hi;
    extremes(fit, &lo, &hi);
    double w_lo = FR_TWO_PI * fit->freq[lo], w_hi = FR_TWO_PI * fit->freq[hi];
    double k_lo = w_lo * w_lo, k_hi = w_hi * w_hi;
    double kt = clamp(2.0 * (k_lo - k_hi), 0.1 * k_lo, 0.9 * k_lo);
    double a_lo = fit->amp[lo] / (fabs(fit->sensor) * pow(w_lo, fit->kind));
    double a_hi = fit->amp[hi] / (fabs(fit->sensor) * pow(w_hi, fit->kind));
    double zeta0 = 0.5 * fmin(fit->zeta[lo], fit->zeta[hi]);
    double slope = 1.0;
    if (a_hi > a_lo && fit->zeta[lo] > zeta0 && fit->zeta[hi] > zeta0)
        slope = log((fit->zeta[hi] - zeta0) / (fit->zeta[lo] - zeta0)) / log(a_hi / a_lo);
    p[FRICREG_FIT_FS] = kt * a_hi;
    p[FRICREG_FIT_KT] = kt;
    p[FRICREG_FIT_CHI] = clamp(slope - 1.0, -0.9, 3.0);
    p[FRICREG_FIT_BETA] = 1.0;
    p[FRICREG_FIT_ZETA0] = zeta0;
    p[FRICREG_FIT_K0] = k_lo - kt;
}

static const char *name(const fricreg_fit *fit, int j)
{
    (void)fit;
    return fr_fit_param_name(j);
}

/* Each level by Brent's method on its amplitude equation (modal_iwan.h). */
static int eval(fricreg_fit *fit, const double p[], int kind, size_t n, const double amp[],
                double guess[], const struct fr_fit_levels *out, size_t *bad)
{
    (void)guess;
    *bad = FR_FIT_REACHED;
    for (size_t i = 0; i < n; i++) {
        struct fr_level_model m;
        if (fr_modal_iwan_level(p, kind, fit->sensor, amp[i], fit->brent, &m) != 0) {
            *bad = i;
            snprintf(fit->reason, sizeof fit->reason, "K0 = 0 with accelerations");
            return FRICREG_EINVAL;
        }
        out->freq_hz[i] = m.freq_hz;
        out->zeta[i] = m.zeta;
        out->modal[i] = m.modal;
        for (int j = 0; j < FR_FIT_NP; j++) {
            out->dfreq[i * FR_FIT_NP + j] = m.dfreq[j];
            out->dzeta[i * FR_FIT_NP + j] = m.dzeta[j];
        }
    }
    return FRICREG_OK;
}

const struct fr_fit_model fr_fit_modal_iwan_model = {name, fr_fit_param_floor,
                                                     fr_fit_param_in_range, from_levels, eval};
