/* SPDX-License-Identifier: GPL-3.0-or-later */
/* lu.h — internal: the dense LU factors (LAPACK's getrf) of the dynamic stiffnesses, Newton's matrix and M (lu.c). */
#ifndef FRICREG_HB_LU_H
#define FRICREG_HB_LU_H

#include "hb_internal.h"

/* The dense LU factors (lu.c, LAPACK's getrf): A[n n] row-major (complex: (re, im) pairs)
 * factored in place with partial pivoting, its pivots U_kk at A's diagonal, the row
 * interchanges into piv[n]; no allocation, no GSL; n < 2^31. The solves overwrite x[n]
 * (complex: [2n]) with A^-1 x from the factor and piv; every pivot must be nonzero (the callers
 * check them first). */
void fr_hb_lu_factor(double *A, size_t n, int *piv);
void fr_hb_lu_solve_factored(const double *LU, size_t n, const int *piv, double *x);
/* The same for nrhs right-hand sides at once, X[nrhs n] (each x contiguous), one LAPACK call. */
void fr_hb_lu_solve_many(const double *LU, size_t n, const int *piv, size_t nrhs, double *X);
void fr_hb_zlu_factor(double *A, size_t n, int *piv);
void fr_hb_zlu_solve_factored(const double *LU, size_t n, const int *piv, double *x);
/* The complex solve for nrhs right-hand sides at once, X[nrhs 2n] (each x contiguous), one
 * LAPACK call (BLAS 3: the condensation's m + 1 columns). */
void fr_hb_zlu_solve_many(const double *LU, size_t n, const int *piv, size_t nrhs, double *X);
/* The reciprocal 1-norm condition number of the complex matrix whose zlu factor LU[n n] is,
 * estimated from the factor and the matrix's 1-norm norm1 (LAPACK's zgecon: Higham's
 * estimator, O(n²)); work[4 n] and rwork[2 n] scratch. 0 where the factor is singular. */
double fr_hb_zlu_rcond(const double *LU, size_t n, double norm1, double *work, double *rwork);
/* The stability's M^-1 (lu.c): Mlu[n n] holding a mass matrix (the driver's, or a reduced one)
 * factored in place into piv[n], every pivot above 1e-14 of M's largest entry; else
 * FRICREG_ESINGULAR, the message naming the method that needs it. */
int fr_hb_mass_lu(fricreg_hb *hb, const char *fn, const char *method, size_t n, double *Mlu,
                  int *piv);

#endif
