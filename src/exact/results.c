/* SPDX-License-Identifier: GPL-3.0-or-later */
/* results.c — what fricreg_exact reports of the solution held: the state at any t, the
 * switches, the dissipation per forcing cycle and the fraction at rest, from the phases'
 * closed forms (closed_form.c); its time, period and counts. */
#include <math.h>
#include <stdint.h>

#include "base/fr_math.h"
#include "closed_form.h"
#include "exact_internal.h"
#include "fricreg_exact.h"

int fricreg_exact_get_value(const fricreg_exact *ex, int which, double *value)
{
    if (ex == NULL || value == NULL)
        return FRICREG_ENULL;
    switch (which) {
    case FRICREG_EXACT_VALUE_TIME: *value = ex->t_end; return FRICREG_OK;
    case FRICREG_EXACT_VALUE_PERIOD: *value = fr_exact_period(ex); return FRICREG_OK;
    default: return FRICREG_EINVAL;
    }
}

int fricreg_exact_get_stat(const fricreg_exact *ex, int which, int64_t *value)
{
    if (ex == NULL || value == NULL)
        return FRICREG_ENULL;
    if (which < 0 || which >= FR_EXACT_STATS)
        return FRICREG_EINVAL;
    *value = ex->stats[which];
    return FRICREG_OK;
}

/* Index of the phase holding time t: the last one that starts at or before t. */
static size_t phase_at(const fricreg_exact *ex, double t)
{
    size_t lo = 0, hi = ex->n;
    while (hi - lo > 1) {
        size_t mid = lo + (hi - lo) / 2;
        if (ex->ph[mid].t0 <= t)
            lo = mid;
        else
            hi = mid;
    }
    return lo;
}

int fricreg_exact_state(const fricreg_exact *ex, double t, double *x, double *v)
{
    if (ex == NULL || x == NULL || v == NULL)
        return FRICREG_ENULL;
    if (ex->n == 0 || !(t >= 0.0 && t <= ex->t_end))
        return FRICREG_EINVAL;
    fr_exact_phase_state(ex, &ex->ph[phase_at(ex, t)], t, x, v);
    return FRICREG_OK;
}

size_t fricreg_exact_nswitches(const fricreg_exact *ex)
{
    return ex && ex->n > 0 ? ex->n - 1 : 0;
}

int fricreg_exact_switches(const fricreg_exact *ex, size_t n, double times[], int sticks[])
{
    if (ex == NULL || (times == NULL && n > 0))
        return FRICREG_ENULL;
    if (n != fricreg_exact_nswitches(ex))
        return FRICREG_ESIZE;
    for (size_t k = 0; k < n; k++) {
        times[k] = ex->ph[k + 1].t0;
        if (sticks != NULL)
            sticks[k] = ex->ph[k + 1].s == 0;
    }
    return FRICREG_OK;
}

size_t fricreg_exact_ncycles(const fricreg_exact *ex)
{
    return ex ? (size_t)fr_whole_cycles(ex->t_end, fr_exact_period(ex)) : 0;
}

/* Phase k covers [t0_k, t0_{k+1}); the last one ends at t_end. Overlap with [ta, tb]. */
static int overlap(const fricreg_exact *ex, size_t k, double ta, double tb, double *lo, double *hi)
{
    double end = k + 1 < ex->n ? ex->ph[k + 1].t0 : ex->t_end;
    *lo = fmax(ta, ex->ph[k].t0);
    *hi = fmin(tb, end);
    return *hi > *lo;
}

/* Distance slid in [ta, tb]: on a slip x is monotone, so it is |x(hi) - x(lo)| per phase. */
static double slid(const fricreg_exact *ex, double ta, double tb)
{
    double total = 0.0, lo, hi, x_lo, x_hi, v;
    for (size_t k = phase_at(ex, ta); k < ex->n && ex->ph[k].t0 < tb; k++) {
        if (ex->ph[k].s == 0 || !overlap(ex, k, ta, tb, &lo, &hi))
            continue;
        fr_exact_phase_state(ex, &ex->ph[k], lo, &x_lo, &v);
        fr_exact_phase_state(ex, &ex->ph[k], hi, &x_hi, &v);
        total += fabs(x_hi - x_lo);
    }
    return total;
}

int fricreg_exact_dissipation(const fricreg_exact *ex, size_t ncycles, double D[])
{
    if (ex == NULL || (D == NULL && ncycles > 0))
        return FRICREG_ENULL;
    if (ncycles != fricreg_exact_ncycles(ex))
        return FRICREG_ESIZE;
    double T = fr_exact_period(ex);
    /* -∫ x' f dt = mun ∫ |x'| dt on a slip; without friction nothing is dissipated, even where
     * the distance slid overflows (x0 near DBL_MAX: 0 * inf; tests/fuzz/regressions/exact/). */
    for (size_t k = 0; k < ncycles; k++)
        D[k] = ex->mun == 0.0 ? 0.0 : ex->mun * slid(ex, (double)k * T, (double)(k + 1) * T);
    return FRICREG_OK;
}

int fricreg_exact_stick_fraction(const fricreg_exact *ex, double t0, double t1, double *fraction)
{
    if (ex == NULL || fraction == NULL)
        return FRICREG_ENULL;
    if (!(t0 >= 0.0 && t1 > t0 && t1 <= ex->t_end))
        return FRICREG_EINVAL;
    double at_rest = 0.0, lo, hi;
    for (size_t k = phase_at(ex, t0); k < ex->n && ex->ph[k].t0 < t1; k++)
        if (ex->ph[k].s == 0 && overlap(ex, k, t0, t1, &lo, &hi))
            at_rest += hi - lo;
    *fraction = at_rest / (t1 - t0);
    return FRICREG_OK;
}
