/* SPDX-License-Identifier: GPL-3.0-or-later */
/* nma_linear.c — the linear mode a backbone starts from (fricreg_hb_nma): the structure with its
 * elements stuck, K_0 = K + J^T diag(k_r) J (k_r the stuck stiffness of row r of J), and its
 * eigenproblem K_0 φ = ω² M φ, φ^T M φ = 1. A dense model (at most 4096 dofs) is solved whole
 * (nma_eigen.c); a sparse model, of any size, by shift-invert subspace iteration on its sparse
 * factor (nma_sparse_mode.c): the dense solve's eigenvalues carry an absolute error of about
 * eps ‖K_0‖ ‖M^-1‖, which for the low modes of a large structure is far above their
 * relative accuracy from K_0's factor. Then M φ, φ^T C φ and the amplitude of first slip. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "nma_internal.h"

#define MAX_DENSE_DOFS 4096

/* The model's M, K and damping C (or Rayleigh's) as n x n, row-major: a dense model's copied, a
 * sparse one's (its pattern holds both triangles) spread out. */
static void densify(const fricreg_hb *hb, double *M, double *K, double *C)
{
    size_t n = hb->n;
    if (hb->sparse) {
        memset(M, 0, n * n * sizeof *M);
        memset(K, 0, n * n * sizeof *K);
        memset(C, 0, n * n * sizeof *C);
        for (size_t j = 0; j < n; j++)
            for (int64_t p = hb->Dp[j]; p < hb->Dp[j + 1]; p++) {
                size_t i = (size_t)hb->Di[p];
                M[i * n + j] = hb->vM[p];
                K[i * n + j] = hb->vK[p];
                C[i * n + j] = hb->rayleigh ? hb->a0 * hb->vM[p] + hb->a1 * hb->vK[p] : hb->vC[p];
            }
        return;
    }
    memcpy(M, hb->M, n * n * sizeof *M);
    memcpy(K, hb->K, n * n * sizeof *K);
    memcpy(C, hb->C, n * n * sizeof *C);
    if (hb->rayleigh)
        for (size_t k = 0; k < n * n; k++)
            C[k] = hb->a0 * M[k] + hb->a1 * K[k];
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

void fr_hb_nma_stuck_model(const fricreg_hb *hb, double *M, double *K0, double *C)
{
    densify(hb, M, K0, C);
    add_stuck(hb, K0);
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

/* φ's largest entry positive (the sign a mode is reported with). */
static void orient(double *phi, size_t n)
{
    size_t big = 0;
    for (size_t i = 1; i < n; i++)
        if (fabs(phi[i]) > fabs(phi[big]))
            big = i;
    if (phi[big] < 0.0) /* tested once: flipping φ[big] on the way must not stop the loop */
        for (size_t i = 0; i < n; i++)
            phi[i] = -phi[i];
}

/* The eigenvector of mode k from the reduced A (destroyed): φ = L^-T v; ω² into *lambda. */
static int eigen_mode(fricreg_hb *hb, const char *fn, double *A, const double *L, double *V,
                      double *work, size_t k, double *phi, double *lambda)
{
    size_t n = hb->n, bad = 0;
    int status = fr_hb_nma_symmv(A, V, work, n, &bad);
    if (status == FRICREG_ENONFINITE)
        return fr_fail(hb, FRICREG_ENONFINITE,
                       "%s: L^-1 K_0 L^-T (M = L L^T) overflows: entry (%zu, %zu) = %g "
                       "(M and K of scales too far apart)",
                       fn, bad / n, bad % n, A[bad]);
    if (status != FRICREG_OK)
        return fr_fail(hb, FRICREG_EINVAL, "%s: the linearized eigenproblem failed", fn);
    *lambda = work[k];
    fr_hb_nma_back(L, V, n, k, phi);
    return FRICREG_OK;
}

/* The dense model's mode: φ into nma->phi, ω² into *lambda, M and K densified into buf. */
static int dense_mode(fricreg_hb *hb, const char *fn, size_t mode, double *buf,
                      struct fr_hb_nma *nma, double *lambda)
{
    size_t n = hb->n;
    double *M = buf, *K = M + n * n, *C = K + n * n, *V = C + n * n, *work = V + n * n;
    densify(hb, M, K, C);
    add_stuck(hb, K);
    int status = fr_hb_nma_cholesky(M, n);
    if (status != FRICREG_OK)
        return fr_fail(hb, status, "%s: M is not positive definite", fn);
    fr_hb_nma_reduce(M, K, n);
    status = eigen_mode(hb, fn, K, M, V, work, mode, nma->phi, lambda);
    if (status == FRICREG_OK) { /* every mode's ω², for the crossings (nma_crossings.c) */
        memcpy(nma->lambda, work, n * sizeof *work);
        nma->nlambda = n;
    }
    return status;
}

/* Every stuck mode, densified: φ_r into Phi's row r if Phi is not NULL, ω_r² into lambda[n]. */
static int all_modes(fricreg_hb *hb, const char *fn, double *Phi, double *lambda)
{
    size_t n = hb->n;
    double *buf = malloc((4 * n * n + 5 * n) * sizeof *buf);
    if (buf == NULL)
        return fr_fail(hb, FRICREG_ENOMEM, "%s: no memory for the linear modes of %zu dofs", fn, n);
    double *M = buf, *K = M + n * n, *C = K + n * n, *V = C + n * n, *work = V + n * n;
    densify(hb, M, K, C);
    add_stuck(hb, K);
    int status = fr_hb_nma_cholesky(M, n);
    if (status != FRICREG_OK)
        status = fr_fail(hb, status, "%s: M is not positive definite", fn);
    else {
        double l0;
        fr_hb_nma_reduce(M, K, n);
        status = eigen_mode(hb, fn, K, M, V, work, 0, Phi != NULL ? Phi : C, &l0);
    }
    if (status == FRICREG_OK)
        memcpy(lambda, work, n * sizeof *work);
    for (size_t r = 0; r < n && status == FRICREG_OK && Phi != NULL; r++) {
        fr_hb_nma_back(M, V, n, r, Phi + r * n);
        orient(Phi + r * n, n);
    }
    free(buf);
    return status;
}

int fr_hb_nma_modes(fricreg_hb *hb, const char *fn, double *Phi)
{
    double *lambda = malloc(hb->n * sizeof *lambda);
    if (lambda == NULL)
        return fr_fail(hb, FRICREG_ENOMEM, "%s: no memory for %zu modes", fn, hb->n);
    int status = all_modes(hb, fn, Phi, lambda);
    free(lambda);
    return status;
}

/* w = M φ and ξ_k = φ^T C φ (C or Rayleigh's a0 M + a1 K) on the sparse pattern. */
static void sparse_loads(const fricreg_hb *hb, struct fr_hb_nma *nma)
{
    size_t n = hb->n;
    const double *phi = nma->phi;
    double xi = 0.0;
    memset(nma->w, 0, n * sizeof *nma->w);
    for (size_t j = 0; j < n; j++)
        for (int64_t p = hb->Dp[j]; p < hb->Dp[j + 1]; p++) {
            size_t i = (size_t)hb->Di[p];
            double c = hb->rayleigh ? hb->a0 * hb->vM[p] + hb->a1 * hb->vK[p] : hb->vC[p];
            nma->w[i] += hb->vM[p] * phi[j];
            xi += phi[i] * c * phi[j];
        }
    nma->xi_k = xi;
}

int fr_hb_nma_linear(fricreg_hb *hb, const char *fn, size_t mode, struct fr_hb_nma *nma)
{
    size_t n = hb->n;
    double lambda = 0.0, *buf = NULL;
    int status;
    if (hb->sparse)
        status = fr_hb_nma_sparse_mode(hb, fn, mode, nma->phi, &lambda);
    else if (n > MAX_DENSE_DOFS) /* a dense model is sparse above this size: kept as a guard */
        return fr_fail(hb, FRICREG_EINVAL,
                       "%s: the linear mode of a dense model of %zu dofs (the dense eigensolver "
                       "takes at most %d)",
                       fn, n, MAX_DENSE_DOFS);
    else if ((buf = malloc((4 * n * n + 5 * n) * sizeof *buf)) == NULL)
        return fr_fail(hb, FRICREG_ENOMEM, "%s: no memory for the linear modes of %zu dofs", fn, n);
    else
        status = dense_mode(hb, fn, mode, buf, nma, &lambda);
    if (status == FRICREG_OK && !(lambda > 0.0))
        status = fr_fail(hb, FRICREG_EINVAL,
                         "%s: mode %zu of the structure with its elements stuck has omega^2 = %g "
                         "(K + J^T diag(kt) J must be positive definite)",
                         fn, mode, lambda);
    if (status == FRICREG_OK) {
        double *phi = nma->phi;
        orient(phi, n);
        nma->omega_k = sqrt(lambda);
        if (hb->sparse)
            sparse_loads(hb, nma);
        else {
            double *M = buf, *K = M + n * n, *C = K + n * n;
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
        }
        nma->a_stick = stick_amplitude(hb, phi);
    }
    free(buf);
    if (status == FRICREG_OK && hb->sparse && n <= FR_HB_NMA_SPARSE_ALL_MODES &&
        (status = all_modes(hb, fn, NULL, nma->lambda)) == FRICREG_OK)
        nma->nlambda = n; /* a small sparse model's every mode, for the crossings */
    return status;
}
