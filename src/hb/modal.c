/* SPDX-License-Identifier: GPL-3.0-or-later */
/* modal.c — the solves Y_h = D_h^-1 [J^T | P_h] through the modes of (K, M) where the damping
 * is proportional. With K Φ = M Φ Λ, Φ^T M Φ = I (LAPACK's dsygvd, once a model) and
 * C = a0 M + a1 K, every D_h(Ω) = K − (hΩ)² M + i hΩ C is diagonal in the modes:
 *
 *     D_h^-1 = Φ diag(1/d_k) Φ^T,   d_k = λ_k (1 + i w a1) + i w a0 − w²,   w = hΩ,
 *
 * (the nonlinear modes' damping −xi M adds −i w xi; their modal option drops a0 and a1), so a
 * frequency costs one real product Φ X a harmonic (4 n² (m + 1) flops), where the LU costs
 * 8 n³/3 + 8 n² (m + 1). The Ω derivatives are dynamic.c's products with vectors, from Y_h as
 * the LU's. The same Y_h to rounding: M's condition number bounds how far the modes' solves
 * can leave the LU's, so the modes serve only where M's reciprocal condition number is at
 * least FR_HB_MODAL_MIN_RCOND. */
#include <complex.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "modal.h"
#include "base/free_all.h"
#include "base/lapack.h"

void fr_hb_modal_free(fricreg_hb *hb)
{
    FR_FREE_ALL(hb->modes, hb->jmodes);
    hb->modes = hb->jmodes = NULL;
    hb->modes_serial = hb->jmodes_serial = 0;
}

/* M's reciprocal condition number in the 1-norm, from its Cholesky factor in the scratch
 * hb->D (LAPACK's dpotrf and dpocon); 0 where M is not positive definite or memory is short. */
static double mass_rcond(fricreg_hb *hb)
{
    int n = (int)hb->n, info = 0;
    double *L = hb->D, norm1 = 0.0, rcond = 0.0;
    for (size_t i = 0; i < hb->n; i++) {
        double sum = 0.0;
        for (size_t j = 0; j < hb->n; j++)
            sum += fabs(hb->M[i * hb->n + j]);
        norm1 = fmax(norm1, sum);
    }
    memcpy(L, hb->M, hb->n * hb->n * sizeof(double));
    dpotrf_("L", &n, L, &n, &info, 1);
    double *work = malloc(3 * hb->n * sizeof(double));
    int *iwork = malloc(hb->n * sizeof(int));
    if (info == 0 && work != NULL && iwork != NULL)
        dpocon_("L", &n, L, &n, &norm1, &rcond, work, iwork, &info, 1);
    free(work);
    free(iwork);
    return info == 0 ? rcond : 0.0;
}

/* The modes of (K, M) into hb->modes (column-major, M-normalized) and hb->lambda, K and M
 * copied into the scratch hb->D (2 n² doubles); 0 on success. */
static int compute_modes(fricreg_hb *hb)
{
    size_t nn = hb->n * hb->n;
    int n = (int)hb->n, one = 1, lwork = -1, liwork = -1, iq = 0, info = 0;
    double wq = 0.0, *A = hb->D, *B = hb->D + nn;
    if (hb->modes == NULL && (hb->modes = malloc((nn + hb->n) * sizeof(double))) == NULL)
        return -1;
    hb->lambda = hb->modes + nn;
    memcpy(A, hb->K, nn * sizeof(double));
    memcpy(B, hb->M, nn * sizeof(double));
    dsygvd_(&one, "V", "L", &n, A, &n, B, &n, hb->lambda, &wq, &lwork, &iq, &liwork, &info, 1, 1);
    lwork = (int)wq;
    liwork = iq;
    double *work = malloc(((size_t)lwork + (size_t)liwork) * sizeof(double));
    if (work == NULL)
        return -1;
    dsygvd_(&one, "V", "L", &n, A, &n, B, &n, hb->lambda, work, &lwork, (int *)(work + lwork),
            &liwork, &info, 1, 1);
    free(work);
    if (info == 0)
        memcpy(hb->modes, A, nn * sizeof(double));
    return info;
}

/* The rows of J in the modes, hb->jmodes = (J Φ) column-major m × n (dgemm), and the scratch
 * hb->xmodal [2 n (m + 1)] for the modal coordinates of a solve; 0 on success. */
static int project_rows(fricreg_hb *hb)
{
    size_t n = hb->n, m = hb->m;
    if (hb->jmodes_rows != m) {
        free(hb->jmodes);
        hb->jmodes = malloc((m * n + 2 * n * (m + 1)) * sizeof(double));
        hb->jmodes_rows = hb->jmodes == NULL ? 0 : m;
        if (hb->jmodes == NULL)
            return -1;
    }
    hb->xmodal = hb->jmodes + m * n;
    int rows = (int)m, cols = (int)n;
    double one = 1.0, zero = 0.0;
    /* row-major J (m × n) is column-major J^T: (J Φ)[e + k m] = sum_i J[e n + i] Φ[i + k n] */
    dgemm_("T", "N", &rows, &cols, &cols, &one, hb->J, &cols, hb->modes, &cols, &zero, hb->jmodes,
           &rows, 1, 1);
    return 0;
}

int fr_hb_modal_ready(fricreg_hb *hb)
{
    int proportional = hb->rayleigh || hb->no_c || hb->c_zero;
    if (hb->sparse || !proportional || hb->n < hb->modal_min || hb->m == 0)
        return 0;
    unsigned long now = hb->mk_serial + 1;
    if (hb->modes_failed == now)
        return 0;
    if (hb->modes_serial != now) {
        int fails = mass_rcond(hb) < FR_HB_MODAL_MIN_RCOND || compute_modes(hb) != 0;
        hb->modes_serial = fails ? 0 : now;
        hb->modes_failed = fails ? now : 0;
        hb->jmodes_serial = 0;
        if (fails)
            return 0;
    }
    if (hb->jmodes_serial != hb->model_serial + 1 || hb->jmodes_rows != hb->m) {
        if (project_rows(hb) != 0)
            return 0;
        hb->jmodes_serial = hb->model_serial + 1;
    }
    return 1;
}

/* The damping's coefficients in the modes: c_k = cm + ck λ_k (cm = a0 − xi, ck = a1; with
 * no_c or a zero damping matrix, −xi and 0). */
static void damping_terms(const fricreg_hb *hb, double *cm, double *ck)
{
    int rayleigh = hb->rayleigh && !hb->no_c;
    *cm = (rayleigh ? hb->a0 : 0.0) - hb->xi;
    *ck = rayleigh ? hb->a1 : 0.0;
}

/* X (row-major n × (m + 1), complex) = diag(s_k) Φ^T [J^T | P_h]: the modal coordinates of the
 * right-hand sides scaled by s_k = 1/d_k; the load column P_1 = pc − i ps at h = 1, 0 at
 * other h. */
static void scale_modal(fricreg_hb *hb, int h, const double complex *s, double *X)
{
    size_t n = hb->n, m = hb->m, w = m + 1;
    for (size_t k = 0; k < n; k++) {
        const double *phi = hb->modes + k * n, *jk = hb->jmodes + k * m;
        double complex load = 0.0;
        if (h == 1)
            for (size_t i = 0; i < n; i++)
                load += phi[i] * (hb->pc[i] - I * hb->ps[i]);
        double *row = X + 2 * k * w;
        for (size_t e = 0; e < m; e++) {
            row[2 * e] = creal(s[k]) * jk[e];
            row[2 * e + 1] = cimag(s[k]) * jk[e];
        }
        row[2 * m] = creal(s[k] * load);
        row[2 * m + 1] = cimag(s[k] * load);
    }
}

/* out (row-major n × (m + 1), complex) = Φ X: column-major, out^T = X^T Φ^T with X^T the real
 * 2 (m + 1) × n of X's interleaved parts. */
static void from_modes(fricreg_hb *hb, const double *X, double *out)
{
    int rows = (int)hb->n, cols = (int)(2 * (hb->m + 1));
    double one = 1.0, zero = 0.0;
    dgemm_("N", "T", &cols, &rows, &rows, &one, X, &cols, hb->modes, &rows, &zero, out, &cols, 1,
           1);
}

int fr_hb_modal_solve(fricreg_hb *hb, const char *fn, int h, double omega)
{
    size_t n = hb->n, w = hb->m + 1;
    double cm, ck, wh = h * omega, scale = 0.0, least = INFINITY;
    size_t at = 0;
    damping_terms(hb, &cm, &ck);
    double complex *s = (double complex *)hb->colw; /* [n] complex */
    for (size_t k = 0; k < n; k++) {
        double lk = hb->lambda[k], ck_k = cm + ck * lk;
        double complex d = lk - wh * wh + I * wh * ck_k;
        scale = fmax(scale, fabs(lk) + wh * wh + wh * fabs(ck_k));
        if (cabs(d) < least)
            least = cabs(d), at = k;
        s[k] = 1.0 / d;
    }
    if (!(least > 1e-14 * scale) || !isfinite(scale))
        return fr_fail(hb, FRICREG_ESINGULAR,
                       "%s: %s is singular at Omega = %g (mode %zu of (K, M): |d| = %g, the "
                       "matrices' scale %g)",
                       fn, h == 0 ? "K" : "the dynamic stiffness D_h", omega, at, least, scale);
    scale_modal(hb, h, s, hb->xmodal);
    from_modes(hb, hb->xmodal, hb->Y + 2 * (size_t)h * n * w);
    return FRICREG_OK;
}
