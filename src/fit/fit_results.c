/* SPDX-License-Identifier: GPL-3.0-or-later */
/* fit_results.c — a fit's getters (fricreg_fit.h): readable only after a successful run. */
#include <string.h>

#include "fit_internal.h"

/* FRICREG_OK if fit holds a fit and np is the parameter count, else the status (recorded). */
static int check_fit(const fricreg_fit *cfit, const char *who, size_t np)
{
    fricreg_fit *fit = (fricreg_fit *)cfit; /* the error record only: logically const */
    if (!fit->have_fit)
        return fr_fail(fit, FRICREG_EINVAL,
                       "%s: no fit (no run has succeeded since the last "
                       "setter)",
                       who);
    if (np != fit->np)
        return fr_fail(fit, FRICREG_ESIZE, "%s: np = %zu, not the model's %zu parameters%s", who,
                       np, fit->np, fit->hb != NULL ? "" : " (FRICREG_FIT_NPARAMS)");
    return FRICREG_OK;
}

static int fail_null(const fricreg_fit *fit, const char *who, const char *what)
{
    return fr_fail((fricreg_fit *)fit, FRICREG_ENULL, "%s: %s", who, what);
}

int fricreg_fit_get_params(const fricreg_fit *fit, size_t np, double p[])
{
    if (fit == NULL)
        return FRICREG_ENULL;
    if (p == NULL)
        return fail_null(fit, "get_params", "p is NULL");
    int st = check_fit(fit, "get_params", np);
    if (st == FRICREG_OK)
        memcpy(p, fit->result.p, np * sizeof *p);
    return st;
}

int fricreg_fit_get_covariance(const fricreg_fit *fit, size_t np, double cov[], double lower[],
                               double upper[])
{
    if (fit == NULL)
        return FRICREG_ENULL;
    if ((lower == NULL) != (upper == NULL))
        return fail_null(fit, "get_covariance", "only one of lower, upper is NULL");
    int st = check_fit(fit, "get_covariance", np);
    if (st != FRICREG_OK)
        return st;
    if (cov != NULL)
        memcpy(cov, fit->result.cov, np * np * sizeof *cov);
    if (lower != NULL) {
        memcpy(lower, fit->result.lower, np * sizeof *lower);
        memcpy(upper, fit->result.upper, np * sizeof *upper);
    }
    return FRICREG_OK;
}

int fricreg_fit_get_identifiability(const fricreg_fit *fit, size_t np, double sv[],
                                    double vectors[])
{
    if (fit == NULL)
        return FRICREG_ENULL;
    if (sv == NULL)
        return fail_null(fit, "get_identifiability", "sv is NULL");
    int st = check_fit(fit, "get_identifiability", np);
    if (st != FRICREG_OK)
        return st;
    memcpy(sv, fit->result.sv, np * sizeof *sv);
    if (vectors != NULL)
        memcpy(vectors, fit->result.vectors, np * np * sizeof *vectors);
    return FRICREG_OK;
}

int fricreg_fit_get_residuals(const fricreg_fit *fit, size_t n, double r_freq[], double r_zeta[])
{
    if (fit == NULL)
        return FRICREG_ENULL;
    if (r_freq == NULL || r_zeta == NULL)
        return fail_null(fit, "get_residuals", "r_freq or r_zeta is NULL");
    int st = check_fit(fit, "get_residuals", fit->np);
    if (st != FRICREG_OK)
        return st;
    if (n != fit->n)
        return fr_fail((fricreg_fit *)fit, FRICREG_ESIZE,
                       "get_residuals: n = %zu, but %zu "
                       "levels are set",
                       n, fit->n);
    memcpy(r_freq, fit->res_freq, n * sizeof *r_freq);
    memcpy(r_zeta, fit->res_zeta, n * sizeof *r_zeta);
    return FRICREG_OK;
}

int fricreg_fit_get_value(const fricreg_fit *fit, int which, double *value)
{
    if (fit == NULL)
        return FRICREG_ENULL;
    if (value == NULL)
        return fail_null(fit, "get_value", "value is NULL");
    int st = check_fit(fit, "get_value", fit->np);
    if (st != FRICREG_OK)
        return st;
    const struct fr_fit_result *r = &fit->result;
    switch (which) {
    case FRICREG_FIT_COST: *value = r->cost; break;
    case FRICREG_FIT_RESIDUAL_VARIANCE: *value = r->variance; break;
    case FRICREG_FIT_NFEV: *value = (double)r->nfev; break;
    case FRICREG_FIT_NJEV: *value = (double)r->njev; break;
    case FRICREG_FIT_ITERATIONS: *value = (double)r->iterations; break;
    case FRICREG_FIT_BEST_START: *value = (double)r->best_start; break;
    case FRICREG_FIT_STARTS_CONVERGED: *value = (double)r->converged; break;
    case FRICREG_FIT_NFREE: *value = (double)r->nfree; break;
    case FRICREG_FIT_CONDITION: *value = r->condition; break;
    case FRICREG_FIT_NMODEL: *value = (double)r->nmodel; break;
    case FRICREG_FIT_NMARCH: *value = (double)r->marches; break;
    default:
        return fr_fail((fricreg_fit *)fit, FRICREG_EINVAL, "get_value: unknown value %d", which);
    }
    return FRICREG_OK;
}

int fricreg_fit_get_quantile(const fricreg_fit *fit, double *q)
{
    if (fit == NULL)
        return FRICREG_ENULL;
    if (q == NULL)
        return fail_null(fit, "get_quantile", "q is NULL");
    int st = check_fit(fit, "get_quantile", fit->np);
    if (st == FRICREG_OK)
        *q = fit->result.quantile;
    return st;
}
