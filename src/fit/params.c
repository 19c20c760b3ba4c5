/* SPDX-License-Identifier: GPL-3.0-or-later */
/* params.c — the modal Iwan model's parameters: names, ranges and the bounded transformation
 * (params.h). */
#include <math.h>

#include "fricreg_fit.h"
#include "params.h"

static const char *const names[FRICREG_FIT_NPARAMS] = {"F_S", "K_T", "chi", "beta", "zeta0", "K0"};

const char *fr_fit_param_name(int which)
{
    return which >= 0 && which < FRICREG_FIT_NPARAMS ? names[which] : "?";
}

double fr_fit_param_floor(int which)
{
    return which == FRICREG_FIT_CHI ? -1.0 : 0.0;
}

int fr_fit_param_in_range(int which, double v)
{
    if (!isfinite(v))
        return 0;
    int open = which == FRICREG_FIT_FS || which == FRICREG_FIT_KT || which == FRICREG_FIT_CHI;
    return open ? v > fr_fit_param_floor(which) : v >= fr_fit_param_floor(which);
}

int fr_fit_params_in_range(const double p[], int *bad)
{
    for (int j = 0; j < FRICREG_FIT_NPARAMS; j++)
        if (!fr_fit_param_in_range(j, p[j])) {
            *bad = j;
            return 0;
        }
    return 1;
}

/* Bounds further apart than this are taken one-sided (the nearer one's log): the logistic map
 * of so wide a range puts an O(1) parameter's s = (p − lo)/(hi − lo) among the subnormals,
 * where it has no digits left (Fortran's huge(1.0) as "no bound" did). */
#define WIDEST 1e300

static void one_sided_if_wide(double *lo, double *hi)
{
    if (isfinite(*lo) && isfinite(*hi) && !(*hi - *lo <= WIDEST)) {
        if (fabs(*hi) >= fabs(*lo))
            *hi = INFINITY;
        else
            *lo = -INFINITY;
    }
}

double fr_fit_from_theta(double theta, double lo, double hi, double *dp_dtheta)
{
    one_sided_if_wide(&lo, &hi);
    if (isfinite(lo) && isfinite(hi)) {
        double s = 1.0 / (1.0 + exp(-theta));
        *dp_dtheta = (hi - lo) * s * (1.0 - s);
        return lo + (hi - lo) * s;
    }
    if (isfinite(lo) || isfinite(hi)) {
        double e = exp(theta);
        *dp_dtheta = isfinite(lo) ? e : -e;
        return isfinite(lo) ? lo + e : hi - e;
    }
    *dp_dtheta = 1.0;
    return theta;
}

double fr_fit_to_theta(double p, double lo, double hi)
{
    one_sided_if_wide(&lo, &hi);
    if (isfinite(lo) && isfinite(hi))
        return log((p - lo) / (hi - p));
    if (isfinite(lo))
        return log(p - lo);
    return isfinite(hi) ? log(hi - p) : p;
}
