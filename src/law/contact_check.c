/* SPDX-License-Identifier: GPL-3.0-or-later */
/* contact_check.c — the contexts' checks of per-contact arrays (contact_check.h). */
#include <float.h>
#include <math.h>

#include "contact_check.h"
#include "fricreg.h"

int fr_check_contact_array(struct fr_error *err, const char *what, size_t m, size_t ctx_m, size_t n,
                           const double a[])
{
    if (m != ctx_m)
        return fr_error_set(err, FRICREG_ESIZE, "%s: m = %zu, context has %zu contacts", what, m,
                            ctx_m);
    if (a == NULL)
        return fr_error_set(err, FRICREG_ENULL, "%s: array is NULL", what);
    for (size_t k = 0; k < n; k++)
        if (!isfinite(a[k]))
            return fr_error_set(err, FRICREG_ENONFINITE, "%s: element %zu is not finite", what, k);
    return FRICREG_OK;
}

int fr_check_bounds(struct fr_error *err, size_t m, size_t ctx_m, const double mun[], double max)
{
    int status = fr_check_contact_array(err, "set_bounds", m, ctx_m, m, mun);
    if (status != FRICREG_OK)
        return status;
    for (size_t i = 0; i < m; i++) {
        if (mun[i] < 0.0)
            return fr_error_set(err, FRICREG_EINVAL, "set_bounds: mun[%zu] = %g is negative", i,
                                mun[i]);
        if (mun[i] > max)
            return fr_error_set(err, FRICREG_EINVAL, "set_bounds: mun[%zu] = %g is above %g", i,
                                mun[i], max);
    }
    return FRICREG_OK;
}
