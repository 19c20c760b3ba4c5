/* SPDX-License-Identifier: GPL-3.0-or-later */
/* point_stability.c — the stability of a stored point or of the last solution
 * (fricreg_hb_point_stability, fricreg_hb_point_exponents): read from the points' extras,
 * which the forced response stores, or from the last solution's, which the stability
 * (floquet/) computed. Here, above both, since floquet/ is below the points' store. */
#include <string.h>

#include "forced_internal.h"
#include "floquet/stability_method.h"

/* The stability record of stored point k or of the last solution (FRICREG_HB_SOLUTION) into
 * *x: x[2] stable, x[3] the largest |μ|, x[4 ..] the 2n exponents (re, im). */
static int stability_record(fricreg_hb *hb, const char *fn, size_t k, const double **x)
{
    if (!fr_hb_stability_on(hb))
        return fr_fail(hb, FRICREG_EINVAL, "%s: stability is off (fricreg_hb_set_stability)", fn);
    if (k == FRICREG_HB_SOLUTION) {
        if (!hb->have_solution)
            return fr_fail(hb, FRICREG_EINVAL,
                           "%s: no solution (none yet, or the model changed since)", fn);
        *x = fr_hb_stability_record(hb);
        return FRICREG_OK;
    }
    size_t npts = fr_hb_points_held(hb);
    if (k >= npts)
        return fr_fail(hb, FRICREG_EINVAL, "%s: k = %zu, %zu points stored", fn, k, npts);
    *x = hb->forced->xpts + k * hb->forced->xpts_stride;
    return FRICREG_OK;
}

int fricreg_hb_point_stability(fricreg_hb *hb, size_t k, int *stable, double *mu_max)
{
    static const char fn[] = "point_stability";
    if (hb == NULL)
        return FRICREG_ENULL;
    if (stable == NULL || mu_max == NULL)
        return fr_fail(hb, FRICREG_ENULL, "%s: %s is NULL", fn,
                       stable == NULL ? "stable" : "mu_max");
    const double *x = NULL;
    int status = stability_record(hb, fn, k, &x);
    if (status != FRICREG_OK)
        return status;
    *stable = x[2] != 0.0;
    *mu_max = x[3];
    return FRICREG_OK;
}

int fricreg_hb_point_exponents(fricreg_hb *hb, size_t k, size_t nexp, double exponents[])
{
    static const char fn[] = "point_exponents";
    if (hb == NULL)
        return FRICREG_ENULL;
    if (exponents == NULL)
        return fr_fail(hb, FRICREG_ENULL, "%s: exponents is NULL", fn);
    if (nexp != 2 * hb->n)
        return fr_fail(hb, FRICREG_ESIZE, "%s: nexp = %zu, the driver has 2 ndof = %zu", fn, nexp,
                       2 * hb->n);
    const double *x = NULL;
    int status = stability_record(hb, fn, k, &x);
    if (status != FRICREG_OK)
        return status;
    memcpy(exponents, x + 4, 4 * hb->n * sizeof(double));
    return FRICREG_OK;
}
