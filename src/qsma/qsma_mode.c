/* SPDX-License-Identifier: GPL-3.0-or-later */
/* qsma_mode.c — the mode quasi-static modal analysis loads along: mode k of the structure with
 * its sliders stuck, K_0 φ = ω_k² M φ, φ^T M φ = 1 (LAPACK's dsygvd, the divide and conquer
 * generalized symmetric solver), oriented as fricreg_hb_nma orients its own (the largest entry
 * positive) so that the two analyses name the same amplitude; and its derivative in the
 * sliders' stiffnesses (Nelson's bordered form: the eigenvector's equation with the mass
 * normalization appended, nonsingular for a simple ω_k). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/lapack.h"
#include "qsma_internal.h"

/* φ's largest entry positive (fricreg_hb_nma's sign). */
static void orient(double *phi, size_t n)
{
    size_t big = 0;
    for (size_t i = 1; i < n; i++)
        if (fabs(phi[i]) > fabs(phi[big]))
            big = i;
    if (phi[big] < 0.0)
        for (size_t i = 0; i < n; i++)
            phi[i] = -phi[i];
}

/* dsygvd on A (K_0, destroyed: the eigenvectors) and B (M, destroyed), eigenvalues into w. */
static int eigen(fricreg_hb *hb, const char *fn, double *A, double *B, double *w, size_t n)
{
    int nn = (int)n, itype = 1, lwork = -1, liwork = -1, info = 0, iq = 0;
    double wq = 0.0;
    dsygvd_(&itype, "V", "U", &nn, A, &nn, B, &nn, w, &wq, &lwork, &iq, &liwork, &info, 1, 1);
    lwork = (int)wq;
    liwork = iq;
    double *work = malloc((size_t)lwork * sizeof *work);
    int *iwork = malloc((size_t)liwork * sizeof *iwork);
    if (work == NULL || iwork == NULL)
        info = -1000;
    else
        dsygvd_(&itype, "V", "U", &nn, A, &nn, B, &nn, w, work, &lwork, iwork, &liwork, &info, 1,
                1);
    free(work);
    free(iwork);
    if (info == -1000)
        return fr_fail(hb, FRICREG_ENOMEM, "%s: no memory for the eigensolver", fn);
    if (info > nn)
        return fr_fail(hb, FRICREG_ENOTPSD, "%s: M is not positive definite", fn);
    if (info != 0)
        return fr_fail(hb, FRICREG_ENONFINITE,
                       "%s: the stuck structure's eigenproblem failed (LAPACK dsygvd info %d)", fn,
                       info);
    return FRICREG_OK;
}

/* b = M φ, c = C φ, φ^T K φ and ζ_k = φ^T C φ / (2 ω_k). */
static void loads(struct fr_qsma *s)
{
    size_t n = s->n;
    double xi = 0.0, kk = 0.0;
    for (size_t i = 0; i < n; i++) {
        double mi = 0.0, ci = 0.0, ki = 0.0;
        for (size_t j = 0; j < n; j++) {
            mi += s->M[i * n + j] * s->phi[j];
            ci += s->C[i * n + j] * s->phi[j];
            ki += s->K[i * n + j] * s->phi[j];
        }
        s->b[i] = mi;
        s->c[i] = ci;
        xi += s->phi[i] * ci;
        kk += s->phi[i] * ki;
    }
    s->zeta_k = xi / (2.0 * s->omega_k);
    s->phik = kk;
}

int fr_qsma_mode(fricreg_hb *hb, const char *fn, size_t mode, struct fr_qsma *s)
{
    size_t n = s->n;
    double *buf = malloc((2 * n * n + n) * sizeof *buf);
    if (buf == NULL)
        return fr_fail(hb, FRICREG_ENOMEM, "%s: no memory for the linear modes of %zu dofs", fn, n);
    double *A = buf, *B = A + n * n, *w = B + n * n;
    fr_qsma_assemble(s, hb->J, A);
    memcpy(B, s->M, n * n * sizeof *B);
    for (size_t k = 0; k < 2 * n * n; k++)
        if (!isfinite(buf[k])) {
            free(buf);
            return fr_fail(hb, FRICREG_ENONFINITE, "%s: K_0 or M is not finite", fn);
        }
    int status = eigen(hb, fn, A, B, w, n);
    if (status == FRICREG_OK && !(w[mode] > 0.0))
        status = fr_fail(hb, FRICREG_EINVAL,
                         "%s: mode %zu of the structure with its elements stuck has omega^2 = %g "
                         "(K + J^T diag(kt) J must be positive definite)",
                         fn, mode, w[mode]);
    if (status == FRICREG_OK) {
        memcpy(s->phi, A + mode * n, n * sizeof *s->phi); /* column-major: column mode */
        orient(s->phi, n);
        s->omega_k = sqrt(w[mode]);
        loads(s);
    }
    free(buf);
    return status;
}

/* The bordered matrix, column-major of order n + 1, LU-factored. */
static int bordered(const struct fr_qsma *s, const double *J, double *A, int *piv)
{
    size_t n = s->n, N = n + 1;
    double *K0 = A + N * N, w2 = s->omega_k * s->omega_k;
    fr_qsma_assemble(s, J, K0);
    for (size_t j = 0; j < n; j++) {
        for (size_t i = 0; i < n; i++)
            A[j * N + i] = K0[j * n + i] - w2 * s->M[j * n + i];
        A[j * N + n] = s->b[j];
        A[n * N + j] = s->b[j];
    }
    A[n * N + n] = 0.0;
    return fr_qsma_lu(A, N, piv);
}

int fr_qsma_shape(fricreg_hb *hb, const char *fn, const struct fr_qsma *s, size_t np,
                  const double *dk, double *w, double *domk, double *dzk)
{
    size_t n = s->n, N = n + 1, m = s->m;
    double *A = malloc((N * N + n * n + N * np + m) * sizeof *A);
    int *piv = malloc(N * sizeof *piv);
    if (A == NULL || piv == NULL) {
        free(A);
        free(piv);
        return fr_fail(hb, FRICREG_ENOMEM, "%s: no memory for the mode shape's derivative", fn);
    }
    double *rhs = A + N * N + n * n, *jphi = rhs + N * np;
    int status = bordered(s, hb->J, A, piv);
    if (status != FRICREG_OK)
        status = fr_fail(hb, FRICREG_ESINGULAR,
                         "%s: the stuck mode is repeated (its bordered eigenvector equation is "
                         "singular): its shape has no derivative",
                         fn);
    for (size_t r = 0; r < m; r++) {
        jphi[r] = 0.0;
        for (size_t i = 0; i < n; i++)
            jphi[r] += hb->J[r * n + i] * s->phi[i];
    }
    for (size_t p = 0; p < np && status == FRICREG_OK; p++) { /* −dK_0 φ, dω_k² = φ^T dK_0 φ */
        double *f = rhs + p * N, dw2 = 0.0;
        memset(f, 0, N * sizeof *f);
        for (size_t r = 0; r < m; r++) {
            double d = dk[p * m + r];
            for (size_t i = 0; i < n && d != 0.0; i++)
                f[i] -= d * hb->J[r * n + i] * jphi[r];
            dw2 += d * jphi[r] * jphi[r];
        }
        domk[p] = dw2 / (2.0 * s->omega_k);
    }
    int nn = (int)N, nrhs = (int)np, info = 0;
    if (status == FRICREG_OK && np > 0)
        dgetrs_("N", &nn, &nrhs, A, &nn, piv, rhs, &nn, &info, 1);
    for (size_t p = 0; p < np && status == FRICREG_OK; p++) {
        const double *dphi = rhs + p * N;
        double cd = 0.0;
        for (size_t i = 0; i < n; i++) {
            double mi = 0.0;
            for (size_t j = 0; j < n; j++)
                mi += s->M[i * n + j] * dphi[j];
            w[p * n + i] = mi;
            cd += s->c[i] * dphi[i];
        }
        /* ζ_k = φ^T C φ / (2 ω_k) */
        dzk[p] = cd / s->omega_k - s->zeta_k * domk[p] / s->omega_k;
    }
    free(A);
    free(piv);
    return status;
}
