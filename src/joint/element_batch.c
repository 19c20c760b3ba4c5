/* SPDX-License-Identifier: GPL-3.0-or-later */
/* element_batch.c — fricreg_element_eval over many points of one type (fricreg_element.h):
 * every point checked first, then each evaluated as fricreg_element_eval evaluates it, so a
 * failed call writes nothing and a good one equals the calls point by point bit for bit. */
#include "element_kind.h"

/* The first point whose inputs the kind's check refuses (npoints if none), and its status. */
static size_t first_bad_point(const fricreg_element_type *type, size_t npoints,
                              const double *params, size_t params_stride, const double *state_in,
                              const double *u, int *status)
{
    const struct fr_element_kind *kind = type->kind;
    size_t nstate = kind->nstate(type->ns), dim = (size_t)kind->dim;
    for (size_t i = 0; i < npoints; i++) {
        *status = kind->check(type, params + params_stride * i, state_in + nstate * i, u + dim * i,
                              NULL, 0);
        if (*status != FRICREG_OK)
            return i;
    }
    *status = FRICREG_OK;
    return npoints;
}

int fricreg_element_eval_batch(const fricreg_element_type *type, size_t npoints,
                               const double params[], size_t params_stride, const double state_in[],
                               const double u[], double f[], double dfdu[], double dfdp[],
                               double state_out[], size_t *bad_point)
{
    if (npoints == 0)
        return FRICREG_OK;
    int status = FRICREG_OK;
    if (type == NULL || params == NULL || state_in == NULL || u == NULL || f == NULL ||
        state_out == NULL)
        status = FRICREG_ENULL;
    else if (params_stride != 0 && params_stride < type->kind->nparams(type->ns))
        status = FRICREG_EINVAL;
    if (status != FRICREG_OK) {
        if (bad_point != NULL)
            *bad_point = npoints;
        return status;
    }
    size_t bad = npoints;
    if (type->kind->batch != NULL) { /* the law's own loop */
        status = type->kind->batch(type, npoints, params, params_stride, state_in, u, f, dfdu, dfdp,
                                   state_out, &bad);
        if (status != FRICREG_OK && bad_point != NULL)
            *bad_point = bad;
        return status;
    }
    bad = first_bad_point(type, npoints, params, params_stride, state_in, u, &status);
    if (status != FRICREG_OK) {
        if (bad_point != NULL)
            *bad_point = bad;
        return status;
    }
    const struct fr_element_kind *kind = type->kind;
    size_t dim = (size_t)kind->dim, np = kind->nparams(type->ns), nstate = kind->nstate(type->ns);
    for (size_t i = 0; i < npoints; i++)
        kind->eval(type, params + params_stride * i, state_in + nstate * i, u + dim * i,
                   f + dim * i, dfdu != NULL ? dfdu + dim * dim * i : NULL,
                   dfdp != NULL ? dfdp + dim * np * i : NULL, state_out + nstate * i, NULL);
    return FRICREG_OK;
}
