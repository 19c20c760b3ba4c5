/* SPDX-License-Identifier: GPL-3.0-or-later */
/* richardson.c — Richardson extrapolation with the leading order observed (richardson.h).
 *
 * The table is Romberg's: T[k][0] = v[k], and column j removes the term h^(p + j - 1),
 * T[k][j] = T[k][j-1] + (T[k][j-1] - T[k-1][j-1]) / (2^(p + j - 1) - 1). */
#include <float.h>
#include <math.h>

#include "richardson.h"

#define ORDER_SLACK 0.3 /* |observed - nearest integer| accepted as that integer */
#define ROUNDING_ULPS 32.0

/* The leading order the last three values show, or NaN. */
static double observed_order(const double v[], int levels)
{
    if (levels < 3)
        return NAN;
    double d1 = v[levels - 2] - v[levels - 3], d2 = v[levels - 1] - v[levels - 2];
    return d1 / d2 > 0.0 ? log2(d1 / d2) : NAN;
}

static int clean_order(double observed)
{
    double p = round(observed);
    return isfinite(observed) && fabs(observed - p) <= ORDER_SLACK && p >= 1.0 &&
           p <= FR_RICHARDSON_MAX_ORDER;
}

/* Whether every value agrees with the last to rounding: nothing left to extrapolate. */
static int converged(const double v[], int levels)
{
    double last = v[levels - 1], tol = ROUNDING_ULPS * DBL_EPSILON * fabs(last);
    for (int k = 0; k < levels - 1; k++)
        if (!(fabs(v[k] - last) <= tol))
            return 0;
    return 1;
}

void fr_richardson(const double v[], int levels, int declared, struct fr_richardson *out)
{
    double t[FR_RICHARDSON_MAX_LEVELS] = {0}; /* levels >= 2 fill what is read */
    int fallback = declared >= 1 ? declared : 1;
    out->observed = NAN;
    out->flagged = 0;
    out->order = fallback;
    if (converged(v, levels)) {
        out->value = v[levels - 1];
        out->error = fabs(v[levels - 1] - v[levels - 2]);
        return;
    }
    out->observed = observed_order(v, levels);
    if (clean_order(out->observed))
        out->order = (int)round(out->observed);
    else
        out->flagged = levels >= 3;
    for (int k = 0; k < levels; k++)
        t[k] = v[k];
    double left = t[levels - 1]; /* T[L-1][j-1] before column j */
    for (int j = 1; j < levels; j++) {
        double divisor = ldexp(1.0, out->order + j - 1) - 1.0;
        left = t[levels - 1];
        for (int k = levels - 1; k >= j; k--)
            t[k] += (t[k] - t[k - 1]) / divisor;
    }
    out->value = t[levels - 1];
    out->error = fabs(t[levels - 1] - left);
    /* Without a clean order the table's own difference can be as wrong as the order: no
     * less than the last step of the raw sequence, which the finest value's error is within
     * when the sequence converges at least linearly with ratio 2. */
    if (out->flagged)
        out->error = fmax(out->error, fabs(v[levels - 1] - v[levels - 2]));
}
