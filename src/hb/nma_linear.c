/* SPDX-License-Identifier: GPL-3.0-or-later */
/* nma_linear.c — the linear mode a backbone starts from (fricreg_hb_nma): the structure with its
 * elements stuck, K_0 = K + J^T diag(k_r) J (k_r the stuck stiffness of row r of J), its
 * eigenproblem K_0 φ = ω² M φ reduced to a symmetric one by the Cholesky factor M = L L^T,
 * (L^-1 K_0 L^-T) v = ω² v, φ = L^-T v (so φ^T M φ = 1), by GSL's gsl_eigen_symmv (Golub & Van
 * Loan, Matrix Computations, 4th ed., Sec. 8.7.2). The Cholesky factor is written here, not
 * GSL's: GSL reports a matrix that is not positive definite through its process-wide error
 * handler, which aborts by default, and the check is the factor itself. Dense: up to 4096
 * dofs, a sparse model's matrices densified. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_eigen.h>

#include "base/eigen.h"
#include "nma_internal.h"

#define MAX_DENSE_DOFS 4096

void fr_hb_nma_row(const fricreg_hb *hb, size_t r, double *k, double *limit)
{
    size_t e = r / hb->rpe;
    *k = 0.0;
    *limit = INFINITY;
    if (hb->nl != NULL) { /* kt, mu, n0, kn: closed at rest when N0 > 0 */
        size_t me = hb->me;
        double kt = hb->nl[e], mu = hb->nl[me + e], n0 = hb->nl[2 * me + e],
               kn = hb->nl[3 * me + e];
        int normal = r % 2 == 1;
        if (n0 > 0.0) {
            *k = normal ? kn : mu > 0.0 ? kt : 0.0;
            *limit = normal ? (kn > 0.0 ? n0 / kn : INFINITY) : mu > 0.0 ? mu * n0 / kt : INFINITY;
        }
        return;
    }
    const double *ks, *phi;
    size_t ns = fr_hb_sliders(hb, e, &ks, &phi);
    for (size_t s = 0; s < ns; s++)
        if (phi[s] > 0.0) { /* a slider of slip force 0 carries nothing */
            *k += ks[s];
            *limit = fmin(*limit, phi[s] / ks[s]);
        }
}

/* The model's M, K and damping C (or Rayleigh's) as dense n x n, row-major. */
static void densify(const fricreg_hb *hb, double *M, double *K, double *C)
{
    size_t n = hb->n;
    if (!hb->sparse) {
        memcpy(M, hb->M, n * n * sizeof *M);
        memcpy(K, hb->K, n * n * sizeof *K);
        memcpy(C, hb->C, n * n * sizeof *C);
    } else {
        memset(M, 0, n * n * sizeof *M);
        memset(K, 0, n * n * sizeof *K);
        memset(C, 0, n * n * sizeof *C);
        for (size_t j = 0; j < n; j++)
            for (int64_t p = hb->Dp[j]; p < hb->Dp[j + 1]; p++) {
                size_t i = (size_t)hb->Di[p];
                M[i * n + j] = hb->vM[p];
                K[i * n + j] = hb->vK[p];
                C[i * n + j] = hb->vC[p];
            }
    }
    if (hb->rayleigh)
        for (size_t k = 0; k < n * n; k++)
            C[k] = hb->a0 * M[k] + hb->a1 * K[k];
}

/* M = L L^T in place (the lower triangle, the upper zeroed): 0, or FRICREG_ENOTPSD when a pivot
 * is not above 1e-14 of M's largest diagonal entry. */
static int cholesky(double *M, size_t n)
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

/* A = L^-1 K L^-T in place of K (L lower, from cholesky). */
static void reduce(const double *L, double *K, size_t n)
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

/* K_0 = K + J^T diag(k_r) J in place of K. */
static void add_stuck(const fricreg_hb *hb, double *K)
{
    size_t n = hb->n;
    for (size_t r = 0; r < hb->m; r++) {
        double k, limit;
        fr_hb_nma_row(hb, r, &k, &limit);
        const double *Jr = hb->J + r * n;
        for (size_t i = 0; i < n && k > 0.0; i++)
            for (size_t j = 0; j < n; j++)
                K[i * n + j] += k * Jr[i] * Jr[j];
    }
}

/* The smallest modal amplitude at which a row of J reaches its first slip (or opening) along
 * φ: min_r limit_r / |J_r φ|; infinite if none does. */
static double stick_amplitude(const fricreg_hb *hb, const double *phi)
{
    size_t n = hb->n;
    double a = INFINITY;
    for (size_t r = 0; r < hb->m; r++) {
        double k, limit, q = 0.0;
        fr_hb_nma_row(hb, r, &k, &limit);
        for (size_t i = 0; i < n; i++)
            q += hb->J[r * n + i] * phi[i];
        if (fabs(q) > 0.0 && isfinite(limit))
            a = fmin(a, limit / fabs(q));
    }
    return a;
}

/* The eigenvector of mode k from the reduced A (destroyed): φ = L^-T v, its largest entry
 * positive; ω² into *lambda. */
static int eigen_mode(fricreg_hb *hb, const char *fn, double *A, const double *L, double *V,
                      double *work, size_t k, double *phi, double *lambda)
{
    size_t n = hb->n;
    gsl_matrix_view Av = gsl_matrix_view_array(A, n, n), Vv = gsl_matrix_view_array(V, n, n);
    gsl_vector_view ev = gsl_vector_view_array(work, n);
    gsl_eigen_symmv_workspace ws = {n, work + n, work + 2 * n, work + 3 * n, work + 4 * n};
    /* finite M and K of scales far apart (K 1e300, M 1e-300) overflow in L^-1 K_0 L^-T; the
     * eigensolver would refuse it (GSL_EDOM) without saying why */
    for (size_t e = 0; e < n * n; e++)
        if (!isfinite(A[e]))
            return fr_fail(hb, FRICREG_ENONFINITE,
                           "%s: L^-1 K_0 L^-T (M = L L^T) overflows: entry (%zu, %zu) = %g "
                           "(M and K of scales too far apart)",
                           fn, e / n, e % n, A[e]);
    /* on finite input gsl_eigen_symmv fails only on sizes, which match here */
    if (fr_eigen_symmv(&Av.matrix, &ev.vector, &Vv.matrix, &ws) != 0)
        return fr_fail(hb, FRICREG_EINVAL, "%s: the linearized eigenproblem failed", fn);
    *lambda = work[k];
    for (size_t i = n; i-- > 0;) { /* L^T φ = v */
        double s = V[i * n + k];
        for (size_t j = i + 1; j < n; j++)
            s -= L[j * n + i] * phi[j];
        phi[i] = s / L[i * n + i];
    }
    size_t big = 0;
    for (size_t i = 1; i < n; i++)
        if (fabs(phi[i]) > fabs(phi[big]))
            big = i;
    for (size_t i = 0; i < n && phi[big] < 0.0; i++)
        phi[i] = -phi[i];
    return FRICREG_OK;
}

int fr_hb_nma_linear(fricreg_hb *hb, const char *fn, size_t mode, struct fr_hb_nma *nma)
{
    size_t n = hb->n;
    if (n > MAX_DENSE_DOFS)
        return fr_fail(hb, FRICREG_EINVAL,
                       "%s: the linear mode of a model of %zu dofs (the dense eigensolver takes "
                       "at most %d)",
                       fn, n, MAX_DENSE_DOFS);
    double *buf = malloc((4 * n * n + 5 * n) * sizeof *buf);
    if (buf == NULL)
        return fr_fail(hb, FRICREG_ENOMEM, "%s: no memory for the linear modes of %zu dofs", fn, n);
    double *M = buf, *K = M + n * n, *C = K + n * n, *V = C + n * n, *work = V + n * n;
    densify(hb, M, K, C);
    add_stuck(hb, K);
    double lambda = 0.0;
    int status = cholesky(M, n);
    if (status != FRICREG_OK)
        status = fr_fail(hb, status, "%s: M is not positive definite", fn);
    if (status == FRICREG_OK) {
        reduce(M, K, n);
        status = eigen_mode(hb, fn, K, M, V, work, mode, nma->phi, &lambda);
    }
    if (status == FRICREG_OK && !(lambda > 0.0))
        status = fr_fail(hb, FRICREG_EINVAL,
                         "%s: mode %zu of the structure with its elements stuck has omega^2 = %g "
                         "(K + J^T diag(kt) J must be positive definite)",
                         fn, mode, lambda);
    if (status == FRICREG_OK) {
        const double *phi = nma->phi;
        nma->omega_k = sqrt(lambda);
        nma->xi_k = 0.0;
        densify(hb, M, K, C); /* M and K were overwritten */
        for (size_t i = 0; i < n; i++) {
            double mi = 0.0, ci = 0.0;
            for (size_t j = 0; j < n; j++) {
                mi += M[i * n + j] * phi[j];
                ci += C[i * n + j] * phi[j];
            }
            nma->w[i] = mi;
            nma->xi_k += phi[i] * ci;
        }
        nma->a_stick = stick_amplitude(hb, phi);
    }
    free(buf);
    return status;
}
