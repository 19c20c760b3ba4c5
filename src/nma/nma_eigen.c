/* SPDX-License-Identifier: GPL-3.0-or-later */
/* nma_eigen.c — the dense generalized symmetric eigenproblem K φ = λ M φ (M positive definite)
 * of the nonlinear modes' linear mode (nma_internal.h): reduced to a symmetric one by the
 * Cholesky factor M = L L^T, (L^-1 K L^-T) v = λ v, φ = L^-T v (so φ^T M φ = 1), solved by
 * GSL's gsl_eigen_symmv (Golub & Van Loan, Matrix Computations, 4th ed., Sec. 8.7.2). Used on
 * the whole model (a dense model, nma_linear.c) and on the Rayleigh–Ritz projection of the
 * sparse subspace iteration (nma_sparse_mode.c). The Cholesky factor is written here, not
 * GSL's: GSL reports a matrix that is not positive definite through its process-wide error
 * handler, which aborts by default, and the check is the factor itself. */
#include <math.h>

#include "base/eigen.h"
#include "nma_internal.h"

int fr_hb_nma_cholesky(double *M, size_t n)
{
    double dmax = 0.0;
    for (size_t i = 0; i < n; i++)
        dmax = fmax(dmax, M[i * n + i]);
    for (size_t j = 0; j < n; j++) {
        double d = M[j * n + j];
        for (size_t k = 0; k < j; k++)
            d -= M[j * n + k] * M[j * n + k];
        if (!(d > 1e-14 * dmax))
            return FRICREG_ENOTPSD;
        d = sqrt(d);
        M[j * n + j] = d;
        for (size_t i = j + 1; i < n; i++) {
            double s = M[i * n + j];
            for (size_t k = 0; k < j; k++)
                s -= M[i * n + k] * M[j * n + k];
            M[i * n + j] = s / d;
            M[j * n + i] = 0.0;
        }
    }
    return FRICREG_OK;
}

void fr_hb_nma_reduce(const double *L, double *K, size_t n)
{
    for (size_t c = 0; c < n; c++) /* K <- L^-1 K, column by column */
        for (size_t i = 0; i < n; i++) {
            double s = K[i * n + c];
            for (size_t k = 0; k < i; k++)
                s -= L[i * n + k] * K[k * n + c];
            K[i * n + c] = s / L[i * n + i];
        }
    for (size_t r = 0; r < n; r++) /* K <- K L^-T, row by row */
        for (size_t i = 0; i < n; i++) {
            double s = K[r * n + i];
            for (size_t k = 0; k < i; k++)
                s -= K[r * n + k] * L[i * n + k];
            K[r * n + i] = s / L[i * n + i];
        }
}

int fr_hb_nma_symmv(double *A, double *V, double *work, size_t n, size_t *bad)
{
    /* finite M and K of scales far apart (K 1e300, M 1e-300) overflow in L^-1 K L^-T; the
     * eigensolver would refuse it (GSL_EDOM) without saying why */
    for (size_t e = 0; e < n * n; e++)
        if (!isfinite(A[e])) {
            *bad = e;
            return FRICREG_ENONFINITE;
        }
    gsl_matrix_view Av = gsl_matrix_view_array(A, n, n), Vv = gsl_matrix_view_array(V, n, n);
    gsl_vector_view ev = gsl_vector_view_array(work, n);
    gsl_eigen_symmv_workspace ws = {n, work + n, work + 2 * n, work + 3 * n, work + 4 * n};
    /* on finite input gsl_eigen_symmv fails only on sizes, which match here */
    return fr_eigen_symmv(&Av.matrix, &ev.vector, &Vv.matrix, &ws) != 0 ? FRICREG_EINVAL
                                                                        : FRICREG_OK;
}

void fr_hb_nma_back(const double *L, const double *V, size_t n, size_t c, double *phi)
{
    for (size_t i = n; i-- > 0;) { /* L^T φ = v */
        double s = V[i * n + c];
        for (size_t j = i + 1; j < n; j++)
            s -= L[j * n + i] * phi[j];
        phi[i] = s / L[i * n + i];
    }
}
