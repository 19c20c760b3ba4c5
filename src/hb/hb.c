/* SPDX-License-Identifier: GPL-3.0-or-later */
/* hb.c — the harmonic-balance driver's life cycle (fricreg_hb.h): create with the defaults of
 * every setting, free, the clone at other harmonics (forced/truncation.c), the solver's settings that
 * change those defaults, and the error record. The model is set in model.c, the elements in
 * elements.c. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "base/sparse_factor.h"
#include "element_store.h"
#include "hb_internal.h"
#include "joint/aft_march.h"
#include "rows.h"
#include "sparse.h"
#include "capacitance.h"
#include "modal.h"
#include "newton_matrix.h"
#include "hb.h"
#include "busy.h"
#include "base/free_all.h"

#define MAX_DENSE_DOFS 4096
#define MAX_DOFS ((size_t)1 << 24)

int fricreg_hb_create(size_t ndof, size_t m, int harmonics, fricreg_hb **out)
{
    if (out == NULL)
        return FRICREG_ENULL;
    if (ndof == 0 || ndof > MAX_DOFS || m == 0 || harmonics < 1 ||
        harmonics > FRICREG_HB_MAX_HARMONICS)
        return FRICREG_EINVAL;
    /* no bound on the elements but the memory: tables that size_t cannot count are none (the
     * buffers' own sizes are checked in rows.c) */
    if (m >= SIZE_MAX / (4 * sizeof(size_t)))
        return FRICREG_ENOMEM;
    fricreg_hb *hb = calloc(1, sizeof *hb);
    if (hb == NULL)
        return FRICREG_ENOMEM;
    size_t n = ndof, nc = 2 * (size_t)harmonics + 1;
    *hb = (fricreg_hb){.n = n,
                       .me = m,
                       .H = harmonics,
                       .nc = nc,
                       .ns = 1,
                       .tol = 1e-10,
                       .max_iter = 50,
                       .ds0 = 0.02,
                       .ds_min = 1e-6,
                       .ds_max = 0.1,
                       .max_points = 2000,
                       .level = 1.0,
                       .level_sol = 1.0,
                       .factored_omega = NAN,
                       .capacitance_min = FR_HB_CAPACITANCE_MIN,
                       .modal_min = FR_HB_MODAL_MIN_DOFS,
                       .held_min = FR_HB_REFINE_MIN,
                       .c_zero = 1,
                       .capacitance_share = FR_HB_CAPACITANCE_SHARE};
    /* up to 4096 dofs the dense model, as the dense setters leave it; beyond, sparse only */
    int dense = n <= MAX_DENSE_DOFS;
    hb->M = dense ? calloc(3 * n * n, sizeof(double)) : NULL;  /* untouched until set */
    hb->D = dense ? malloc(2 * n * n * sizeof(double)) : NULL; /* n >= 1 */
    hb->piv = dense ? malloc(n * sizeof *hb->piv) : NULL;
    /* the elements' tables and normal laws; the buffers for m elements of one row */
    hb->erow = calloc(4 * (m + 1), sizeof *hb->erow);
    hb->kind = calloc(m, sizeof *hb->kind);
    hb->etype = calloc(m, sizeof *hb->etype);
    hb->nl = calloc(4 * m, sizeof *hb->nl);
    struct fr_hb_rows b;
    int rows = hb->erow && hb->kind && hb->etype && hb->nl ? fr_hb_rows_alloc(hb, m, m, &b)
                                                           : FRICREG_ENOMEM;
    if (rows == FRICREG_OK) {
        hb->ejq = hb->erow + m + 1;
        hb->eso = hb->ejq + m + 1;
        hb->epo = hb->eso + m + 1;
        fr_hb_rows_install(hb, m, m, &b);
    }
    int status = fricreg_aft_create(harmonics, 0, &hb->aft);
    int started = fr_cholmod_start(&hb->cc) == FRICREG_OK;
    if ((dense && (!hb->M || !hb->D || !hb->piv)) || rows != FRICREG_OK || status != FRICREG_OK ||
        !started || (!dense && fr_hb_sparse_defaults(hb) != FRICREG_OK)) {
        fricreg_hb_free(hb);
        return FRICREG_ENOMEM;
    }
    if (dense) {
        hb->C = hb->M + n * n;
        hb->K = hb->C + n * n;
        for (size_t k = 0; k < n; k++)
            hb->M[k * n + k] = 1.0;
    }
    fr_hb_rows_set(hb);
    *out = hb;
    return FRICREG_OK;
}

void fricreg_hb_free(fricreg_hb *hb)
{
    if (hb == NULL)
        return;
    FR_FREE_ALL(hb->M, hb->J, hb->D, hb->Y, hb->Z, hb->G, hb->fq, hb->piv, hb->piv2);
    for (int part = 0; part < FR_HB_PARTS; part++)
        if (hb->release[part] != NULL)
            hb->release[part](hb);
    fricreg_aft_free(hb->aft);
    fricreg_aft_free(hb->aft_half);
    FR_FREE_ALL(hb->half, hb->sk, hb->nl, hb->erow, hb->kind, hb->etype, hb->ep);
    fr_aft_march_free(hb->march);
    fr_hb_sparse_free(hb);
    fr_hb_capacitance_free(hb);
    fr_hb_modal_free(hb);
    fr_cholmod_finish(&hb->cc);
    free(hb);
}

/* A driver at harmonics H with src's model (dense or sparse M, C, K, Rayleigh damping),
 * elements (Jenkins, Iwan, lift-off or 3-D contact), excitation, Newton's settings, monitor and
 * bound: the companion of fricreg_hb_truncation_error. Nothing of src changes. */
int fr_hb_clone(const fricreg_hb *src, int harmonics, fricreg_hb **out)
{
    fricreg_hb *hb = NULL;
    size_t n = src->n, me = src->me;
    int status = fricreg_hb_create(n, me, harmonics, &hb);
    if (status != FRICREG_OK)
        return status;
    if (fr_hb_store_copy(hb, src) != FRICREG_OK ||
        (src->sparse && fr_hb_sparse_copy(hb, src) != FRICREG_OK)) {
        fricreg_hb_free(hb);
        return FRICREG_ENOMEM;
    }
    if (!src->sparse) /* M, C, K: one block */
        memcpy(hb->M, src->M, 3 * n * n * sizeof(double));
    hb->rayleigh = src->rayleigh;
    hb->c_zero = src->c_zero;
    hb->a0 = src->a0;
    hb->a1 = src->a1;
    memcpy(hb->pc, src->pc, 2 * n * sizeof(double)); /* pc, ps */
    hb->tol = src->tol;
    hb->max_iter = src->max_iter;
    hb->capacitance_min = src->capacitance_min;
    hb->capacitance_share = src->capacitance_share;
    hb->modal_min = src->modal_min;
    hb->held_min = src->held_min;
    (void)fr_hb_newton_matrix_room(hb); /* none: the dense LU serves */
    hb->monitor = src->monitor;
    hb->monitor_user = src->monitor_user;
    hb->max_iterations = src->max_iterations;
    *out = hb;
    return FRICREG_OK;
}

int fricreg_hb_set_newton(fricreg_hb *hb, double tol, int max_iter)
{
    if (hb == NULL || hb->busy)
        return fr_hb_refuse(hb, "set_newton");
    if (!isfinite(tol))
        return fr_fail(hb, FRICREG_ENONFINITE, "set_newton: tol = %g", tol);
    if (!(tol > 0.0 && tol < 1.0) || max_iter < 1 || max_iter > 1000)
        return fr_fail(hb, FRICREG_EINVAL,
                       "set_newton: tol = %g must be in (0, 1), max_iter = %d in [1, 1000]", tol,
                       max_iter);
    hb->tol = tol;
    hb->max_iter = max_iter;
    return FRICREG_OK;
}

int fricreg_hb_set_newton_solver(fricreg_hb *hb, int solver)
{
    /* the least nq solved by the capacitance, its largest share of rows off Ĵ's diagonal, and
     * the least order of a dense matrix solved by refinement on an earlier one's factor */
    static const struct {
        size_t min;
        double share;
        size_t held_min;
    } SOLVERS[] = {[FRICREG_HB_NEWTON_AUTO] = {FR_HB_CAPACITANCE_MIN, FR_HB_CAPACITANCE_SHARE,
                                               FR_HB_REFINE_MIN},
                   [FRICREG_HB_NEWTON_DENSE] = {SIZE_MAX, 0.0, SIZE_MAX},
                   [FRICREG_HB_NEWTON_CAPACITANCE] = {0, 1.0, FR_HB_REFINE_MIN}};
    if (hb == NULL || hb->busy)
        return fr_hb_refuse(hb, "set_newton_solver");
    if (solver < FRICREG_HB_NEWTON_AUTO || solver > FRICREG_HB_NEWTON_CAPACITANCE)
        return fr_fail(hb, FRICREG_EINVAL,
                       "set_newton_solver: solver = %d is none of enum fricreg_hb_newton_solver",
                       solver);
    size_t min = hb->capacitance_min;
    double share = hb->capacitance_share;
    hb->capacitance_min = SOLVERS[solver].min;
    hb->capacitance_share = SOLVERS[solver].share;
    if (!fr_hb_newton_matrix_room(hb)) {
        hb->capacitance_min = min;
        hb->capacitance_share = share;
        return fr_fail(hb, FRICREG_ENOMEM, "set_newton_solver: no room for the capacitance");
    }
    hb->held_min = SOLVERS[solver].held_min;
    return FRICREG_OK;
}

int fricreg_hb_set_receptance(fricreg_hb *hb, int method)
{
    static const size_t LEAST_DOFS[] = {[FRICREG_HB_RECEPTANCE_AUTO] = FR_HB_MODAL_MIN_DOFS,
                                        [FRICREG_HB_RECEPTANCE_LU] = SIZE_MAX,
                                        [FRICREG_HB_RECEPTANCE_MODES] = 0};
    if (hb == NULL || hb->busy)
        return fr_hb_refuse(hb, "set_receptance");
    if (method < FRICREG_HB_RECEPTANCE_AUTO || method > FRICREG_HB_RECEPTANCE_MODES)
        return fr_fail(hb, FRICREG_EINVAL,
                       "set_receptance: method = %d is none of enum fricreg_hb_receptance", method);
    if (hb->modal_min != LEAST_DOFS[method]) { /* the factors were the other route's */
        hb->modal_min = LEAST_DOFS[method];
        hb->factored_omega = NAN;
        hb->k_kept = 0;
    }
    return FRICREG_OK;
}

int fricreg_hb_set_continuation(fricreg_hb *hb, double ds, double ds_min, double ds_max,
                                size_t max_points)
{
    if (hb == NULL || hb->busy)
        return fr_hb_refuse(hb, "set_continuation");
    if (!isfinite(ds) || !isfinite(ds_min) || !isfinite(ds_max))
        return fr_fail(hb, FRICREG_ENONFINITE,
                       "set_continuation: ds = %g, ds_min = %g, ds_max = %g", ds, ds_min, ds_max);
    if (!(ds_min > 0.0 && ds_min <= ds && ds <= ds_max && ds_max <= 1.0) || max_points < 2)
        return fr_fail(hb, FRICREG_EINVAL,
                       "set_continuation: need 0 < ds_min = %g <= ds = %g <= ds_max = %g <= 1 and "
                       "max_points = %zu >= 2",
                       ds_min, ds, ds_max, max_points);
    hb->ds0 = ds;
    hb->ds_min = ds_min;
    hb->ds_max = ds_max;
    hb->max_points = max_points;
    return FRICREG_OK;
}

FR_ERROR_GETTERS(fricreg_hb, "NULL HB driver")
