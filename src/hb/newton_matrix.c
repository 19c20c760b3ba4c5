/* SPDX-License-Identifier: GPL-3.0-or-later */
/* newton_matrix.c — Newton's matrix of (R), plain or bordered, by one of two factors: the
 * dense LU of order nd (residual.c), or where Ĵ's rows are mostly a stiffness on the diagonal
 * (stuck elements, closed contacts' normal rows) the capacitance's of order s (capacitance.c).
 * The choice is by the count s alone, so equal Jacobians choose alike. A large dense matrix
 * is first solved by iterative refinement on the LU factor of an earlier one (Wilkinson's,
 * there on the factor of the matrix itself: N. J. Higham, Accuracy and Stability of Numerical
 * Algorithms, 2nd ed., 2002, Ch. 12): Newton's matrices of successive iterations and of a
 * continuation's successive points differ little, so the refinement contracts fast, at one
 * product with the matrix (unformed) and one solve with the factor an iteration, where the
 * LU of its own costs 2 nd³/3. It is formed and factored only where the refinement does not
 * converge. */
#include <math.h>
#include <string.h>

#include "capacitance.h"
#include "lu.h"
#include "newton_matrix.h"
#include "residual.h"

/* The recorded matrix formed into A (over the factor held there). */
static void dense(fricreg_hb *hb)
{
    size_t nq = hb->nq, nd = hb->newton_nd;
    hb->held_nd = 0;
    fr_hb_matrix(hb, hb->jq, hb->A, nd);
    if (nd > nq) {
        for (size_t j = 0; j < nq; j++)
            hb->A[j * nd + nq] = hb->bcol[j];
        memcpy(hb->A + nq * nd, hb->brow, nd * sizeof(double));
    }
}

/* out = A x for the recorded matrix, unformed: x + Ĝ (Ĵ x) (each element's Jacobian block on
 * its own coefficients, into t; then the condensation, residual.c's fr_hb_apply), and on a
 * border col x_nq and row^T x. */
static void apply(const fricreg_hb *hb, const double *x, double *t, double *out)
{
    size_t nq = hb->nq, nc = hb->nc, nd = hb->newton_nd;
    for (size_t e = 0; e < hb->me; e++) {
        size_t b = fr_hb_rows_of(hb, e) * nc, at = hb->erow[e] * nc;
        const double *J = fr_hb_block_of(hb, e);
        for (size_t i = 0; i < b; i++) {
            double s = 0.0;
            for (size_t j = 0; j < b; j++)
                s += J[i * b + j] * x[at + j];
            t[at + i] = s;
        }
    }
    fr_hb_apply(hb, hb->G, NULL, 0.0, t, out);
    for (size_t j = 0; j < nq; j++)
        out[j] += x[j];
    if (nd == nq)
        return;
    double s = 0.0;
    for (size_t j = 0; j < nq; j++) {
        out[j] += hb->bcol[j] * x[nq];
        s += hb->brow[j] * x[j];
    }
    out[nq] = s + hb->brow[nq] * x[nq];
}

static double norm_inf(const double *x, size_t n)
{
    double s = 0.0;
    for (size_t j = 0; j < n; j++)
        s = fmax(s, fabs(x[j]));
    return s;
}

/* The refinement's bounds: at most REFINE_ITERATIONS corrections, each shrinking |r| by
 * REFINE_RATE at least (slower: the matrices differ too much, and the matrix's own LU is
 * cheaper; at 85 contacts 0.8 and 40, or 30 with an early exit, gave no faster sweep: their
 * steps fell into a kinked stretch that the default's step over, docs/hb_size.md);
 * converged at |r|∞ <= REFINE_TOL |b|∞, else the LU (where rounding keeps the residual above
 * it, an ill-conditioned matrix). */
#define REFINE_ITERATIONS 20
#define REFINE_RATE 0.5
#define REFINE_TOL 1e-12

/* sol = A⁻¹ rhs by refinement on the factor held: 1 converged, 0 not (sol untouched). */
static int refine(fricreg_hb *hb, const double *rhs, double *sol)
{
    size_t nd = hb->newton_nd;
    double *b = hb->refine, *x = b + nd, *t = x + nd, *r = t + nd;
    memcpy(b, rhs, nd * sizeof(double));
    memcpy(x, rhs, nd * sizeof(double));
    fr_hb_lu_solve_factored(hb->A, nd, hb->piv2, x);
    double bn = norm_inf(b, nd), prev = INFINITY;
    for (int k = 0; k <= REFINE_ITERATIONS; k++) {
        apply(hb, x, t, r);
        for (size_t j = 0; j < nd; j++)
            r[j] = b[j] - r[j];
        double rn = norm_inf(r, nd);
        if (rn <= REFINE_TOL * bn) {
            memcpy(sol, x, nd * sizeof(double));
            return 1;
        }
        if (!(rn <= REFINE_RATE * prev) || k == REFINE_ITERATIONS)
            return 0;
        prev = rn;
        fr_hb_lu_solve_factored(hb->A, nd, hb->piv2, r);
        for (size_t j = 0; j < nd; j++)
            x[j] += r[j];
    }
    return 0;
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
    if (hb->by_capacitance || nd == nq)
        return;
    /* formed at the solve that factors it: until then A keeps the factor held */
    memcpy(hb->bcol, col, nq * sizeof(double));
    memcpy(hb->brow, row, nd * sizeof(double));
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
        if (fr_hb_newton_held(hb) && refine(hb, rhs, sol))
            return FRICREG_OK;
        dense(hb);
        int status = fr_hb_lu_solve(hb, fn, nd, rhs, sol);
        hb->newton_factored = status == FRICREG_OK;
        hb->held_nd = hb->newton_factored ? nd : 0;
        return status;
    }
    int status = fr_hb_capacitance_factor(hb, fn);
    if (status == FR_HB_STUCK_SINGULAR) { /* A0 (the stuck part) singular, A perhaps not */
        const double *col, *row;
        fr_hb_capacitance_border(hb, &col, &row);
        hb->by_capacitance = 0;
        if (nd > hb->nq) {
            memcpy(hb->bcol, col, hb->nq * sizeof(double));
            memcpy(hb->brow, row, nd * sizeof(double));
        }
        return fr_hb_newton_solve(hb, fn, rhs, sol);
    }
    if (status != FRICREG_OK)
        return status;
    hb->held_nd = 0; /* A's factor is no longer the last matrix's */
    fr_hb_capacitance_solve(hb, rhs, sol);
    return FRICREG_OK;
}

int fr_hb_newton_held(const fricreg_hb *hb)
{
    return !hb->by_capacitance && !hb->newton_factored && hb->held_nd == hb->newton_nd &&
           hb->newton_nd >= hb->held_min;
}

void fr_hb_newton_forget(fricreg_hb *hb)
{
    if (!hb->newton_factored)
        hb->held_nd = 0;
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
