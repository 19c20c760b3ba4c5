/* SPDX-License-Identifier: GPL-3.0-or-later */
/* newton_matrix.c — Newton's matrix of (R), plain or bordered, by one of two factors: the
 * dense LU of order nd (residual.c), or where Ĵ's rows are mostly a stiffness on the diagonal
 * (stuck elements, closed contacts' normal rows) the capacitance's of order s (capacitance.c).
 * The choice is by the count s alone, so equal Jacobians choose alike. */
#include <math.h>
#include <string.h>

#include "capacitance.h"
#include "lu.h"
#include "newton_matrix.h"
#include "residual.h"

static void dense(fricreg_hb *hb, size_t nd, const double *col, const double *row)
{
    size_t nq = hb->nq;
    fr_hb_matrix(hb, hb->jq, hb->A, nd);
    if (nd == nq)
        return;
    for (size_t j = 0; j < nq; j++)
        hb->A[j * nd + nq] = col[j];
    memcpy(hb->A + nq * nd, row, nd * sizeof(double));
}

int fr_hb_newton_matrix_room(fricreg_hb *hb)
{
    if (hb->have_elements && hb->nq >= hb->capacitance_min)
        return fr_hb_capacitance_reserve(hb); /* none: the dense LU serves */
    fr_hb_capacitance_free(hb);
    return 1;
}

void fr_hb_newton_matrix(fricreg_hb *hb, size_t nd, const double *col, const double *row)
{
    size_t nq = hb->nq;
    hb->newton_nd = nd;
    hb->by_capacitance = 0;
    hb->newton_factored = 0;
    if (nq >= hb->capacitance_min) {
        /* without the room s = nq + 1 (+ 1), above any share up to 1 */
        size_t s = fr_hb_capacitance_split(hb, nd, col, row) + (nd > nq);
        hb->by_capacitance = (double)s <= hb->capacitance_share * (double)nd;
    }
    if (!hb->by_capacitance)
        dense(hb, nd, col, row);
}

int fr_hb_newton_solve(fricreg_hb *hb, const char *fn, double *rhs, double *sol)
{
    size_t nd = hb->newton_nd;
    if (!hb->by_capacitance) {
        if (hb->newton_factored) {
            if (rhs != sol)
                memcpy(sol, rhs, nd * sizeof *sol);
            fr_hb_lu_solve_factored(hb->A, nd, hb->piv2, sol);
            return FRICREG_OK;
        }
        int status = fr_hb_lu_solve(hb, fn, nd, rhs, sol);
        hb->newton_factored = status == FRICREG_OK;
        return status;
    }
    int status = fr_hb_capacitance_factor(hb, fn);
    if (status == FR_HB_STUCK_SINGULAR) { /* A0 (the stuck part) singular, A perhaps not */
        const double *col, *row;
        fr_hb_capacitance_border(hb, &col, &row);
        hb->by_capacitance = 0;
        dense(hb, nd, col, row);
        return fr_hb_newton_solve(hb, fn, rhs, sol);
    }
    if (status != FRICREG_OK)
        return status;
    fr_hb_capacitance_solve(hb, rhs, sol);
    return FRICREG_OK;
}

double fr_hb_newton_det_sign(const fricreg_hb *hb)
{
    if (hb->by_capacitance)
        return fr_hb_capacitance_det_sign(hb);
    size_t ld = hb->newton_nd;
    double sign = 1.0;
    for (size_t k = 0; k < ld; k++)
        sign *= (hb->A[k * ld + k] < 0.0 ? -1.0 : 1.0) * (hb->piv2[k] != (int)k + 1 ? -1.0 : 1.0);
    return sign;
}
