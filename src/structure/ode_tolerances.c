/* SPDX-License-Identifier: GPL-3.0-or-later */
/* ode_tolerances.c — the absolute tolerances of fricreg_structure_run_ode per component of its
 * state y = (u, v, W_in, E_visc, D_1 … D_m): set by the caller
 * (fricreg_structure_set_ode_abs_tolerances), one scalar, or the rule from eps
 * (FRICREG_ATOL_FROM_EPS), fricreg_sim's rule (src/sim/tolerances.c) carried through J.
 *
 * Law (4) reads the contact velocity zdot_i = sum_j J_ij v_j, which lies inside its band
 * |zdot_i| < eps at a stick while the v_j may be of order 1: a relative tolerance on v, or
 * one atol >= eps, leaves the force of the stick uncontrolled. So each velocity a contact
 * reads is held absolutely, with no relative part, to
 *   atol_v_j = min(1e-3 eps min_{i: J_ij != 0} 1 / sum_k |J_ik|, rtol),
 * which bounds contact i's velocity error by sum_j |J_ij| atol_v_j <= 1e-3 eps: the level
 * fricreg_sim's rule holds a body velocity to (its contacts read one or two bodies with unit
 * weights). The cap rtol (one velocity unit of the model) keeps tight tolerances tight where
 * eps is large, as fricreg_sim's. Everything else keeps GSL's standard level rtol (1 + |y_k|). */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "ctx/ctx_driver.h"
#include "fricreg_sim.h"
#include "structure_internal.h"

#define ATOL_V_PER_EPS 1e-3 /* fricreg_sim's (FR_SIM_ATOL_V_PER_EPS, docs/integrators.md) */

static size_t state_length(const fricreg_structure *s)
{
    return 2 * s->n + 2 + s->m;
}

/* The rule from eps into atol[dim] and, unless NULL, w[dim] (see above), its velocity level
 * scaled by s->tol_scale. */
static void rule(const fricreg_structure *s, double rtol, double atol[], double w[])
{
    size_t n = s->n, dim = state_length(s);
    for (size_t k = 0; k < dim; k++)
        atol[k] = k >= n && k < 2 * n ? INFINITY : rtol; /* INFINITY: no contact reads v_j yet */
    const cholmod_sparse *Jt = s->Jt;                    /* column i: contact i's row of J */
    const SuiteSparse_long *p = Jt->p, *row = Jt->i;
    const double *x = Jt->x;
    double level = ATOL_V_PER_EPS * fr_ctx_eps(s->ctx) * s->tol_scale;
    for (size_t i = 0; i < s->m; i++) {
        double norm = 0.0; /* sum_j |J_ij| */
        for (SuiteSparse_long k = p[i]; k < p[i + 1]; k++)
            norm += fabs(x[k]);
        if (!(norm > 0.0))
            continue;                           /* a contact no dof moves reads no velocity */
        double a = fmax(level / norm, DBL_MIN); /* > 0: the control divides by it */
        for (SuiteSparse_long k = p[i]; k < p[i + 1]; k++)
            if (x[k] != 0.0)
                atol[n + (size_t)row[k]] = fmin(atol[n + (size_t)row[k]], a);
    }
    for (size_t k = 0; k < dim; k++) {
        int read = k >= n && k < 2 * n && atol[k] < INFINITY;
        if (k >= n && k < 2 * n)
            atol[k] = fmin(atol[k], rtol);
        if (w != NULL)
            w[k] = read ? 0.0 : 1.0; /* a velocity a contact reads: no relative part */
    }
}

void fr_ode_tolerances(const fricreg_structure *s, double rtol, double atol, double out[],
                       double w[])
{
    size_t dim = state_length(s);
    if (s->ode_atol != NULL || atol != FRICREG_ATOL_FROM_EPS) {
        for (size_t k = 0; k < dim; k++) {
            out[k] = s->ode_atol != NULL ? s->ode_atol[k] * s->tol_scale : atol;
            if (w != NULL)
                w[k] = 1.0;
        }
        return;
    }
    rule(s, rtol, out, w);
}

int fricreg_structure_set_ode_abs_tolerances(fricreg_structure *s, size_t n, const double atol[])
{
    if (s == NULL || s->running)
        return fr_structure_refuse(s, "set_ode_abs_tolerances");
    size_t dim = state_length(s);
    if (atol == NULL && n != 0)
        return fr_fail(s, FRICREG_ENULL, "set_ode_abs_tolerances: atol is NULL with n = %zu", n);
    if (n != 0 && n != dim)
        return fr_fail(s, FRICREG_ESIZE,
                       "set_ode_abs_tolerances: n = %zu, run_ode's state (u, v, W_in, E_visc, "
                       "D_1 ... D_m) has 2 ndof + 2 + m = %zu components (0 removes them)",
                       n, dim);
    for (size_t k = 0; k < n; k++) {
        if (!isfinite(atol[k]))
            return fr_fail(s, FRICREG_ENONFINITE, "set_ode_abs_tolerances: atol[%zu] is not finite",
                           k);
        if (!(atol[k] > 0.0))
            return fr_fail(s, FRICREG_EINVAL, "set_ode_abs_tolerances: atol[%zu] = %g must be > 0",
                           k, atol[k]);
    }
    double *copy = NULL;
    if (n != 0) {
        copy = malloc(n * sizeof *copy);
        if (copy == NULL)
            return fr_fail(s, FRICREG_ENOMEM, "set_ode_abs_tolerances: out of memory");
        memcpy(copy, atol, n * sizeof *copy);
    }
    free(s->ode_atol);
    s->ode_atol = copy;
    fr_structure_changed(s, FR_CHANGED_ODE_ATOL);
    return FRICREG_OK;
}

int fricreg_structure_get_ode_abs_tolerances(const fricreg_structure *s, size_t n, double atol[])
{
    if (s == NULL || atol == NULL)
        return FRICREG_ENULL;
    size_t dim = state_length(s);
    if (n != dim)
        return FRICREG_ESIZE;
    if (s->ode_atol == NULL && s->ode_rtol == 0.0 && s->ode_atol1 == 0.0) {
        memset(atol, 0, n * sizeof *atol); /* no adaptive call yet */
        return FRICREG_OK;
    }
    if (s->ode_atol1 == FRICREG_ATOL_FROM_EPS && s->ode_atol == NULL && s->Jt == NULL) {
        memset(atol, 0, n * sizeof *atol); /* J was never set: no call ran */
        return FRICREG_OK;
    }
    fr_ode_tolerances(s, s->ode_rtol, s->ode_atol1, atol, NULL);
    return FRICREG_OK;
}
