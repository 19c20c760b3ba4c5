/* SPDX-License-Identifier: GPL-3.0-or-later */
/* starts.c — a fit's starts (starts.h). The first start's parameters the caller did not give
 * come from the levels, read as the model would make them:
 *   K0 + K_T = omega^2 at the smallest amplitude (the joint stuck);
 *   K_T = 2 (omega_lo^2 - omega_hi^2), within 0.1 .. 0.9 of it (the joint's share of the drop);
 *   F_S = K_T a_max, a_max the largest level's modal amplitude (macroslip near the top level);
 *   zeta0 = half the smallest measured zeta; chi + 1 = the slope of log(zeta - zeta0) against
 *   log a between the smallest and largest levels (D/(k a^2) ~ a^(chi+1) below macroslip),
 *   within -0.9 .. 3; beta = 1.
 * A start outside the caller's bounds is moved inside. Where the caller gave starts, the first
 * start is theirs, alone; every other start is about the levels' centre: the least squares has
 * a local minimum wherever a level's amplitude sits on phi_max's kink (the stiffness drops by
 * F_S beta/(c phi_max) there), so the centre in the right regime with many starts about it
 * finds the best far more often than starts about a caller's guess far off (measured: 8
 * starts about two centres missed the best of 64 in 38 of 50 noisy draws; 32 about the
 * levels' in none). The starts after the centre's first move each theta by
 * (2 h - 1) times a span (ln 10 where theta is a log: a factor 10 either way; 2 for a
 * parameter bounded on both sides; 1 + |theta| for none), h the Halton sequence in the k-th
 * prime's base for the k-th free parameter: deterministic, and spread over the box. */
#include <math.h>

#include "fricreg_fit.h"
#include "base/fr_math.h"
#include "params.h"
#include "starts.h"

static const unsigned primes[FR_FIT_NP] = {2, 3, 5, 7, 11, 13};

/* The van der Corput radical inverse of s in base b, in (0, 1) for s >= 1. */
static double halton(size_t s, unsigned b)
{
    double h = 0.0, f = 1.0 / b;
    for (; s > 0; s /= b, f /= b)
        h += f * (double)(s % b);
    return h;
}

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

/* The first start's parameters made from the levels (the header comment's rules). */
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

/* v moved inside (lo, hi) if it is not. */
static double inside(double v, double lo, double hi)
{
    if (v > lo && v < hi)
        return v;
    if (isfinite(lo) && isfinite(hi))
        return 0.5 * (lo + hi);
    return isfinite(lo) ? lo + 1.0 + fabs(lo) : hi - 1.0 - fabs(hi);
}

/* 1 if the caller gave a start to some free parameter. */
static int caller_started(const struct fr_fit_problem *pb)
{
    for (size_t k = 0; k < pb->nfree; k++)
        if (!isnan(pb->fit->par[pb->idx[k]].value))
            return 1;
    return 0;
}

void fr_fit_start(const struct fr_fit_problem *pb, size_t s, double theta[])
{
    const fricreg_fit *fit = pb->fit;
    double guess[FR_FIT_NP];
    from_levels(fit, guess);
    /* The caller's start first, where given; every other start about the levels'. */
    int caller = caller_started(pb), levels_centre = !caller || s > 0;
    size_t h = caller && s > 0 ? s - 1 : s;
    for (size_t k = 0; k < pb->nfree; k++) {
        const struct fr_fit_param *q = &fit->par[pb->idx[k]];
        double p = isnan(q->value) || levels_centre ? inside(guess[pb->idx[k]], q->lo, q->hi)
                                                    : q->value;
        double t = fr_fit_to_theta(p, q->lo, q->hi);
        double span = isfinite(q->lo) && isfinite(q->hi)   ? 2.0
                      : isfinite(q->lo) || isfinite(q->hi) ? log(10.0)
                                                           : 1.0 + fabs(t);
        theta[k] = h == 0 ? t : t + span * (2.0 * halton(h, primes[k]) - 1.0);
    }
}
