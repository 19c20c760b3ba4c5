/* SPDX-License-Identifier: GPL-3.0-or-later */
/* contact_check.c — the contexts' checks of per-contact arrays (contact_check.h). */
#include <float.h>
#include <math.h>

#include "contact_check.h"
#include "fricreg.h"
#include "law_stribeck.h"
#include "plausible.h"

int fr_check_contact_array(struct fr_error *err, const char *what, size_t m, size_t ctx_m, size_t n,
                           const double a[], double max)
{
    if (m != ctx_m)
        return fr_error_set(err, FRICREG_ESIZE, "%s: m = %zu, context has %zu contacts", what, m,
                            ctx_m);
    if (a == NULL)
        return fr_error_set(err, FRICREG_ENULL, "%s: array is NULL", what);
    for (size_t k = 0; k < n; k++)
        if (!isfinite(a[k]))
            return fr_error_set(err, FRICREG_ENONFINITE, "%s: element %zu is not finite", what, k);
    for (size_t k = 0; k < n; k++)
        if (fabs(a[k]) > max)
            return fr_error_set(err, FRICREG_EINVAL, "%s: element %zu = %g is beyond %g", what, k,
                                a[k], max);
    return FRICREG_OK;
}

int fr_check_bounds(struct fr_error *err, size_t m, size_t ctx_m, const double mun[], double max)
{
    int status = fr_check_contact_array(err, "set_bounds", m, ctx_m, m, mun, INFINITY);
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

int fr_check_stribeck(struct fr_error *err, size_t m, size_t ctx_m, const double fs[],
                      const double fk[], const double vs[], const double delta[], double cap)
{
    if (m != ctx_m)
        return fr_error_set(err, FRICREG_ESIZE, "set_stribeck: m = %zu, context has %zu contacts",
                            m, ctx_m);
    char why[160];
    int status = fr_stribeck_check(m, fs, fk, vs, delta, cap, why, sizeof why);
    return status == FRICREG_OK ? status : fr_error_set(err, status, "set_stribeck: %s", why);
}

/* The first k with zdot[k] or a_free[k] not finite, or n: run only when fr_plausible fails,
 * to name the culprit. */
static size_t first_nonfinite(size_t n, const double zdot[], const double a_free[])
{
    size_t k = 0;
    while (k < n && isfinite(zdot[k]) && isfinite(a_free[k]))
        k++;
    return k;
}

int fr_check_eval_inputs(struct fr_error *err, size_t m, size_t ctx_m, size_t n,
                         const double zdot[], const double a_free[], const double f[])
{
    if (m != ctx_m)
        return fr_error_set(err, FRICREG_ESIZE, "eval: m = %zu, context has %zu contacts", m,
                            ctx_m);
    if (zdot == NULL || a_free == NULL || f == NULL)
        return fr_error_set(err, FRICREG_ENULL, "eval: %s is NULL",
                            zdot == NULL     ? "zdot"
                            : a_free == NULL ? "a_free"
                                             : "f");
    size_t k = fr_plausible(n, zdot, a_free, NULL) ? n : first_nonfinite(n, zdot, a_free);
    if (k < n)
        return fr_error_set(err, FRICREG_ENONFINITE, "eval: %s[%zu] is not finite",
                            isfinite(zdot[k]) ? "a_free" : "zdot", k);
    return FRICREG_OK;
}
