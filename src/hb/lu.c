/* SPDX-License-Identifier: GPL-3.0-or-later */
/* lu.c — the harmonic-balance driver's dense LU factors with partial pivoting, real (Newton's
 * matrix) and complex (the dynamic stiffnesses D_h), in place on the driver's arrays, and their
 * solves (hb_internal.h). Outer-product Gaussian elimination with partial pivoting, Golub & Van
 * Loan, Matrix Computations, 4th ed., Alg. 3.4.1: P A = L U with L unit lower triangular below
 * the diagonal and U on and above it; the row interchanges as LAPACK's getrf records them
 * (piv[k]: the row swapped with row k at step k). The pivot is the largest |a_ik| (real) or
 * |Re a_ik| + |Im a_ik| (complex: BLAS's izamax, as LAPACK's zgetrf chooses it); a zero pivot
 * column is left as it is (the caller checks every pivot before a solve).
 *
 * Why not GSL's: GSL 2.7's gsl_linalg_LU_decomp and gsl_linalg_complex_LU_decomp allocate
 * their pivots (gsl_vector_uint_alloc) at every call and use them unchecked, so a failed
 * malloc there calls GSL's error handler (the default aborts) or, with the handler off,
 * crashes. Here every array is the caller's, allocated when the driver is created or its
 * elements are set: no allocation and no GSL error handler. */
#include <math.h>
#include <stddef.h>

#include "hb_internal.h"

void fr_hb_lu_factor(double *A, size_t n, size_t *piv)
{
    for (size_t k = 0; k < n; k++) {
        size_t p = k;
        double best = fabs(A[k * n + k]);
        for (size_t i = k + 1; i < n; i++)
            if (fabs(A[i * n + k]) > best) {
                best = fabs(A[i * n + k]);
                p = i;
            }
        piv[k] = p;
        if (p != k)
            for (size_t j = 0; j < n; j++) {
                double t = A[k * n + j];
                A[k * n + j] = A[p * n + j];
                A[p * n + j] = t;
            }
        double d = A[k * n + k];
        if (d == 0.0)
            continue; /* the column below is 0 too: nothing to eliminate */
        const double *rk = A + k * n;
        for (size_t i = k + 1; i < n; i++) {
            double *ri = A + i * n, l = ri[k] / d;
            ri[k] = l;
            if (l != 0.0)
                for (size_t j = k + 1; j < n; j++)
                    ri[j] -= l * rk[j];
        }
    }
}

void fr_hb_lu_solve_factored(const double *LU, size_t n, const size_t *piv, double *x)
{
    for (size_t k = 0; k < n; k++)
        if (piv[k] != k) {
            double t = x[k];
            x[k] = x[piv[k]];
            x[piv[k]] = t;
        }
    for (size_t i = 1; i < n; i++) { /* L y = P b, L unit lower */
        double s = x[i];
        for (size_t j = 0; j < i; j++)
            s -= LU[i * n + j] * x[j];
        x[i] = s;
    }
    for (size_t i = n; i-- > 0;) { /* U x = y */
        double s = x[i];
        for (size_t j = i + 1; j < n; j++)
            s -= LU[i * n + j] * x[j];
        x[i] = s / LU[i * n + i];
    }
}

/* (a + ib)/(c + id) into q[0..1] by Smith's method (R. L. Smith, "Algorithm 116: Complex
 * division", Comm. ACM 5(8), 1962): no c² + d², which would overflow for entries near 1e154
 * and beyond. */
static void cdiv(double a, double b, double c, double d, double *q)
{
    if (fabs(c) >= fabs(d)) {
        double r = d / c, den = c + d * r;
        q[0] = (a + b * r) / den;
        q[1] = (b - a * r) / den;
    } else {
        double r = c / d, den = c * r + d;
        q[0] = (a * r + b) / den;
        q[1] = (b * r - a) / den;
    }
}

void fr_hb_zlu_factor(double *A, size_t n, size_t *piv)
{
    for (size_t k = 0; k < n; k++) {
        size_t p = k;
        double best = fabs(A[2 * (k * n + k)]) + fabs(A[2 * (k * n + k) + 1]);
        for (size_t i = k + 1; i < n; i++) {
            double v = fabs(A[2 * (i * n + k)]) + fabs(A[2 * (i * n + k) + 1]);
            if (v > best) {
                best = v;
                p = i;
            }
        }
        piv[k] = p;
        if (p != k)
            for (size_t j = 0; j < 2 * n; j++) {
                double t = A[2 * k * n + j];
                A[2 * k * n + j] = A[2 * p * n + j];
                A[2 * p * n + j] = t;
            }
        double dr = A[2 * (k * n + k)], di = A[2 * (k * n + k) + 1];
        if (dr == 0.0 && di == 0.0)
            continue;
        const double *rk = A + 2 * k * n;
        for (size_t i = k + 1; i < n; i++) {
            double *ri = A + 2 * i * n, l[2];
            cdiv(ri[2 * k], ri[2 * k + 1], dr, di, l);
            ri[2 * k] = l[0];
            ri[2 * k + 1] = l[1];
            if (l[0] == 0.0 && l[1] == 0.0)
                continue;
            for (size_t j = k + 1; j < n; j++) {
                double ur = rk[2 * j], ui = rk[2 * j + 1];
                ri[2 * j] -= l[0] * ur - l[1] * ui;
                ri[2 * j + 1] -= l[0] * ui + l[1] * ur;
            }
        }
    }
}

void fr_hb_zlu_solve_factored(const double *LU, size_t n, const size_t *piv, double *x)
{
    for (size_t k = 0; k < n; k++)
        if (piv[k] != k)
            for (int c = 0; c < 2; c++) {
                double t = x[2 * k + c];
                x[2 * k + c] = x[2 * piv[k] + c];
                x[2 * piv[k] + c] = t;
            }
    for (size_t i = 1; i < n; i++) {
        double sr = x[2 * i], si = x[2 * i + 1];
        for (size_t j = 0; j < i; j++) {
            double lr = LU[2 * (i * n + j)], li = LU[2 * (i * n + j) + 1];
            sr -= lr * x[2 * j] - li * x[2 * j + 1];
            si -= lr * x[2 * j + 1] + li * x[2 * j];
        }
        x[2 * i] = sr;
        x[2 * i + 1] = si;
    }
    for (size_t i = n; i-- > 0;) {
        double sr = x[2 * i], si = x[2 * i + 1];
        for (size_t j = i + 1; j < n; j++) {
            double ur = LU[2 * (i * n + j)], ui = LU[2 * (i * n + j) + 1];
            sr -= ur * x[2 * j] - ui * x[2 * j + 1];
            si -= ur * x[2 * j + 1] + ui * x[2 * j];
        }
        cdiv(sr, si, LU[2 * (i * n + i)], LU[2 * (i * n + i) + 1], x + 2 * i);
    }
}
