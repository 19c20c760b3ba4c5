/* SPDX-License-Identifier: GPL-3.0-or-later */
/* lu.c — the harmonic-balance driver's dense LU factors with partial pivoting, real (Newton's
 * matrix) and complex (the dynamic stiffnesses D_h), by LAPACK's dgetrf/dgetrs and
 * zgetrf/zgetrs (hb_internal.h): blocked (BLAS 3), the pivots in the caller's array, no
 * allocation and no GSL error handler (GSL 2.7's LU allocates its pivots at every call, which
 * is why 1.7 had an LU of its own here).
 *
 * The driver's matrices are row-major; LAPACK's are column-major, so it sees and factors A^T:
 * A^T = P L U. U's diagonal, the pivots the callers check, sits where A's diagonal does, and
 * A x = b is (A^T)^T x = b, getrs with TRANS = 'T' (not 'C': the complex D_h is not
 * conjugated). A zero pivot leaves the factor complete with info > 0 (the callers check every
 * pivot before a solve). */
#include <limits.h>
#include <math.h>
#include <stddef.h>

#include "base/lapack.h"
#include "hb_internal.h"
#include "lu.h"

void fr_hb_lu_factor(double *A, size_t n, int *piv)
{
    int order = (int)n, info;
    dgetrf_(&order, &order, A, &order, piv, &info);
}

void fr_hb_lu_solve_many(const double *LU, size_t n, const int *piv, size_t nrhs, double *X)
{
    int order = (int)n, cols = (int)nrhs, info;
    dgetrs_("T", &order, &cols, LU, &order, piv, X, &order, &info, 1);
}

void fr_hb_lu_solve_factored(const double *LU, size_t n, const int *piv, double *x)
{
    fr_hb_lu_solve_many(LU, n, piv, 1, x);
}

void fr_hb_zlu_factor(double *A, size_t n, int *piv)
{
    int order = (int)n, info;
    zgetrf_(&order, &order, A, &order, piv, &info);
}

void fr_hb_zlu_solve_factored(const double *LU, size_t n, const int *piv, double *x)
{
    fr_hb_zlu_solve_many(LU, n, piv, 1, x);
}

void fr_hb_zlu_solve_many(const double *LU, size_t n, const int *piv, size_t nrhs, double *X)
{
    int order = (int)n, cols = (int)nrhs, info;
    zgetrs_("T", &order, &cols, LU, &order, piv, X, &order, &info, 1);
}

double fr_hb_zlu_rcond(const double *LU, size_t n, double norm1, double *work, double *rwork)
{
    int order = (int)n, info;
    double rcond = 0.0;
    zgecon_("1", &order, LU, &order, &norm1, &rcond, work, rwork, &info, 1);
    return rcond;
}

int fr_hb_mass_lu(fricreg_hb *hb, const char *fn, const char *method, size_t n, double *Mlu,
                  int *piv)
{
    double mmax = 0.0;
    for (size_t i = 0; i < n * n; i++)
        mmax = fmax(mmax, fabs(Mlu[i]));
    fr_hb_lu_factor(Mlu, n, piv);
    for (size_t k = 0; k < n; k++)
        if (!(fabs(Mlu[k * n + k]) > 1e-14 * mmax))
            return fr_fail(hb, FRICREG_ESINGULAR,
                           "%s: stability: the mass matrix is singular (pivot %zu of its LU "
                           "factor: %g, largest entry %g): %s needs M^-1",
                           fn, k, Mlu[k * n + k], mmax, method);
    return FRICREG_OK;
}
