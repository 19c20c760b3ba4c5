/* SPDX-License-Identifier: GPL-3.0-or-later */
/* nma_sensitivity_terms.c — two parts of a backbone point's parameter sensitivities
 * (fricreg_hb_nma_point_sensitivities, nma_sensitivity.c) beyond the implicit function
 * theorem's solve with Newton's matrix:
 *
 * The mode shape's terms. The amplitude and phase conditions read s = φ^T M X_1 with φ the stuck
 * structure's mode k, K_0 φ = λ M φ, φ^T M φ = 1, K_0 = K + J^T diag(k_r) J; a stiffness p of
 * the elements moves φ: differentiated, B (dφ, −dλ) = (−dK_0 φ, 0) with the symmetric bordered
 *
 *     B = [ K_0 − λ M   M φ ]
 *         [ φ^T M        0  ],
 *
 * nonsingular for a simple λ, so for any b: b^T dφ = −z^T dK_0 φ = −Σ_r (dk_r/dp)(J_r z)(J_r φ)
 * with B (z, ·) = (b, 0): one solve each for b = M Re X_1, M Im X_1 and, where the modal damping
 * ξ_k = φ^T C φ is in force, C φ (dξ_k/dp = 2 (C φ)^T dφ), whatever the number of parameters.
 *
 * The dofs' first-harmonic amplitudes. X_1 = −D_1^-1 J^T F_1 with D_1 = K − ω² M + i ω (C' −
 * ξ' M) (C' the damping in force, ξ' = ξ less the shift ξ_k or a0), so
 *
 *     dX_1 = −Y_1 dF_1 − dω D_1^-1 (∂D_1/∂ω X_1) + dξ' D_1^-1 (i ω M X_1) − da1 D_1^-1 (i ω K X_1),
 *
 * dF_1 = ∂F_1/∂q dq + ∂F_1/∂p: two (three with Rayleigh's a1) solves with D_1 for all the
 * parameters, and d|X_1| = (Re X Re dX + Im X Im dX) / |X| (0 where X_1 = 0). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "nma_internal.h"
#include "hb/dynamic.h"
#include "hb/lu.h"

/* y = A x for complex x[2n] (interleaved), A the model's M (which 0), K (1) or the damping in
 * force C' − ξ' M (2, as hb/dynamic.c's), dense or on the sparse pattern (both triangles). */
static void times(const fricreg_hb *hb, int which, const double *x, double *y)
{
    size_t n = hb->n;
    memset(y, 0, 2 * n * sizeof *y);
    for (size_t j = 0; j < n; j++) {
        int64_t p0 = hb->sparse ? hb->Dp[j] : 0, p1 = hb->sparse ? hb->Dp[j + 1] : (int64_t)n;
        for (int64_t p = p0; p < p1; p++) {
            size_t i = hb->sparse ? (size_t)hb->Di[p] : (size_t)p, at = i * n + j;
            const double *M = hb->sparse ? hb->vM : hb->M, *K = hb->sparse ? hb->vK : hb->K;
            const double *C = hb->sparse ? hb->vC : hb->C;
            size_t k = hb->sparse ? (size_t)p : at;
            double a = which == 0   ? M[k]
                       : which == 1 ? K[k]
                                    : (hb->no_c       ? 0.0
                                       : hb->rayleigh ? hb->a0 * M[k] + hb->a1 * K[k]
                                                      : C[k]) -
                                          hb->xi * M[k];
            y[2 * i] += a * x[2 * j];
            y[2 * i + 1] += a * x[2 * j + 1];
        }
    }
}

void fr_hb_nma_first_harmonic(const fricreg_hb *hb, const double *f, double *X)
{
    size_t n = hb->n, m = hb->m, w = m + 1, nc = hb->nc;
    const double *Y = hb->Y + 2 * n * w; /* h = 1 */
    for (size_t k = 0; k < n; k++) {
        double re = 0.0, im = 0.0;
        for (size_t r = 0; r < m; r++) { /* −y F, F = fa − i fb */
            const double *y = Y + 2 * (k * w + r);
            double fa = f[r * nc + 1], fb = f[r * nc + 2];
            re -= y[0] * fa + y[1] * fb;
            im -= y[1] * fa - y[0] * fb;
        }
        X[2 * k] = re;
        X[2 * k + 1] = im;
    }
}

int fr_hb_nma_shape_terms(fricreg_hb *hb, const char *fn, const struct fr_hb_nma *nma,
                          const double *X1, size_t np, const double *dk, double *t)
{
    size_t n = hb->n, n1 = n + 1, m = hb->m;
    double *buf = malloc((3 * n * n + n1 * n1 + 3 * n1 + 4 * m) * sizeof *buf);
    int *piv = malloc(n1 * sizeof *piv);
    if (buf == NULL || piv == NULL) {
        free(buf);
        free(piv);
        return fr_fail(hb, FRICREG_ENOMEM, "%s: no memory for the mode shape's derivative", fn);
    }
    double *M = buf, *K0 = M + n * n, *C = K0 + n * n, *B = C + n * n, *Z = B + n1 * n1;
    double *jphi = Z + 3 * n1, *jz = jphi + m, lambda = nma->omega_k * nma->omega_k, bmax = 0.0;
    fr_hb_nma_stuck_model(hb, M, K0, C);
    for (size_t i = 0; i <= n; i++)
        for (size_t j = 0; j <= n; j++) {
            double v = i < n && j < n ? K0[i * n + j] - lambda * M[i * n + j]
                       : i < n        ? nma->w[i]
                       : j < n        ? nma->w[j]
                                      : 0.0;
            B[i * n1 + j] = v;
            bmax = fmax(bmax, fabs(v));
        }
    for (size_t i = 0; i < n; i++) { /* M Re X_1, M Im X_1, C φ */
        double zr = 0.0, zi = 0.0, zc = 0.0;
        for (size_t j = 0; j < n; j++) {
            zr += M[i * n + j] * X1[2 * j];
            zi += M[i * n + j] * X1[2 * j + 1];
            zc += C[i * n + j] * nma->phi[j];
        }
        Z[i] = zr;
        Z[n1 + i] = zi;
        Z[2 * n1 + i] = zc;
    }
    Z[n] = Z[n1 + n] = Z[2 * n1 + n] = 0.0;
    fr_hb_lu_factor(B, n1, piv);
    int status = FRICREG_OK;
    for (size_t k = 0; k < n1 && status == FRICREG_OK; k++)
        if (!(fabs(B[k * n1 + k]) > 1e-14 * bmax))
            status = fr_fail(hb, FRICREG_ESINGULAR,
                             "%s: the stuck structure's mode %zu is repeated (its bordered matrix "
                             "[K_0 - lambda M, M phi; phi^T M, 0] is singular: pivot %zu, %g): "
                             "its shape has no derivative",
                             fn, nma->mode, k, fabs(B[k * n1 + k]));
    if (status == FRICREG_OK) {
        fr_hb_lu_solve_many(B, n1, piv, 3, Z);
        for (size_t r = 0; r < m; r++) {
            const double *Jr = hb->J + r * n;
            double a = 0.0, z[3] = {0.0, 0.0, 0.0};
            for (size_t j = 0; j < n; j++) {
                a += Jr[j] * nma->phi[j];
                for (int b = 0; b < 3; b++)
                    z[b] += Jr[j] * Z[b * n1 + j];
            }
            jphi[r] = a;
            for (int b = 0; b < 3; b++)
                jz[b * m + r] = z[b];
        }
        for (size_t k = 0; k < np; k++)
            for (int b = 0; b < 3; b++) {
                double s = 0.0;
                for (size_t r = 0; r < m; r++)
                    s -= dk[k * m + r] * jz[b * m + r] * jphi[r];
                t[3 * k + b] = s;
            }
    }
    free(buf);
    free(piv);
    return status;
}

/* dF_1 (complex, [2m]) of the parameter: ∂F/∂q dq + ∂F/∂p on each row's first harmonic. */
static void force_change(const fricreg_hb *hb, const double *dq, const double *df, double *dF1)
{
    size_t nc = hb->nc;
    for (size_t e = 0; e < hb->me; e++) {
        size_t rows = fr_hb_rows_of(hb, e), b = rows * nc, at = hb->erow[e] * nc;
        const double *J = fr_hb_block_of(hb, e);
        for (size_t sr = 0; sr < rows; sr++)
            for (size_t c = 1; c <= 2; c++) {
                size_t row = sr * nc + c;
                double v = df != NULL ? df[at + row] : 0.0;
                for (size_t j = 0; j < b; j++)
                    v += J[row * b + j] * dq[at + j];
                dF1[at + row] = v; /* in (R)'s real layout, the first harmonic only */
            }
    }
}

int fr_hb_nma_amplitude_terms(fricreg_hb *hb, const char *fn, double omega, const double *X1,
                              size_t np, const double *dy, size_t nd, const double *df,
                              const double *da1, double *work, double *damp)
{
    size_t n = hb->n, nq = hb->nq;
    double *U = work, *v = U + 6 * n, *dF = v + 2 * n, *dX = dF + nq;
    int direct = 0;
    for (size_t k = 0; k < np; k++)
        direct |= da1[k] != 0.0;
    /* U: D_1^-1 (∂D_1/∂ω X_1), D_1^-1 (i ω M X_1), D_1^-1 (i ω K X_1) */
    times(hb, 0, X1, v);
    times(hb, 2, X1, U);
    for (size_t j = 0; j < n; j++) {
        double cr = U[2 * j], ci = U[2 * j + 1], mr = v[2 * j], mi = v[2 * j + 1];
        U[2 * j] = -2.0 * omega * mr - ci; /* −2ω M X + i C' X */
        U[2 * j + 1] = -2.0 * omega * mi + cr;
        U[2 * (n + j)] = -omega * mi; /* i ω M X */
        U[2 * (n + j) + 1] = omega * mr;
    }
    if (direct) {
        times(hb, 1, X1, v);
        for (size_t j = 0; j < n; j++) {
            U[2 * (2 * n + j)] = -omega * v[2 * j + 1];
            U[2 * (2 * n + j) + 1] = omega * v[2 * j];
        }
    }
    int status = fr_hb_harmonic_solve(hb, fn, 1, omega, direct ? 3 : 2, U);
    if (status != FRICREG_OK)
        return status;
    memset(dF, 0, nq * sizeof *dF);
    for (size_t k = 0; k < np; k++) {
        const double *d = dy + k * nd;
        double dw = d[nq], dxi = d[nq + 1];
        force_change(hb, d, df + k * nq, dF);
        fr_hb_nma_first_harmonic(hb, dF, dX);
        for (size_t j = 0; j < n; j++) {
            double *y = dX + 2 * j, x = hypot(X1[2 * j], X1[2 * j + 1]);
            for (int c = 0; c < 2; c++) {
                y[c] += dxi * U[2 * (n + j) + c] - dw * U[2 * j + c];
                if (direct)
                    y[c] -= da1[k] * U[2 * (2 * n + j) + c];
            }
            damp[k * n + j] = x > 0.0 ? (X1[2 * j] * y[0] + X1[2 * j + 1] * y[1]) / x : 0.0;
        }
    }
    return FRICREG_OK;
}
