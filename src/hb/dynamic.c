/* SPDX-License-Identifier: GPL-3.0-or-later */
/* dynamic.c — the dynamic stiffnesses D_h(Ω) = K − (hΩ)² M + i hΩ C, h = 0..H, factored by
 * LAPACK's complex LU (lu.c; on the driver's arrays, no GSL) or, with Rayleigh damping, solved
 * through the modes of (K, M) (modal.c), their solves Y_h = D_h^-1 [J^T | P_h], and the
 * condensation on the elements:
 * G_h = J Y_h (the receptance between the elements' coordinates), ql_h = J D_h^-1 P_h (their
 * response with the elements removed), and the Ω derivatives of their products,
 * d(J D^-1 B)/dΩ c = −(J D^-1) D' (D^-1 B c), where J D^-1 = (D^-1 J^T)^T because M, C, K (so
 * D) are symmetric: no second solve, and no matrix dG_h/dΩ (a product with a vector c costs
 * O(n m + n²) a harmonic, the matrix O(n m²)). Every pivot is checked before a solve divides by it. */
#include <math.h>
#include <string.h>

#include "hb_internal.h"
#include "dynamic.h"
#include "sparse.h"
#include "lu.h"
#include "modal.h"
#include "base/lapack.h"

/* (a + ib)(c + id) accumulated into out[0..1] with the sign s. */
static inline void cmac(double *out, double s, double a, double b, double c, double d)
{
    out[0] += s * (a * c - b * d);
    out[1] += s * (a * d + b * c);
}

/* The damping in force: C, or a0 M + a1 K, less the nonlinear modes' xi M (C left out when
 * no_c). */
static double damping(const fricreg_hb *hb, size_t idx)
{
    double c = hb->no_c       ? 0.0
               : hb->rayleigh ? hb->a0 * hb->M[idx] + hb->a1 * hb->K[idx]
                              : hb->C[idx];
    return c - hb->xi * hb->M[idx];
}

/* D_h into hb->D; returns the largest |K| + w² |M| + w |C| of an entry: the scale of the terms,
 * not of their sum (K − w² M cancels at a resonance). */
static double form_one(fricreg_hb *hb, int h, double omega)
{
    size_t n = hb->n;
    double w = h * omega, dmax = 0.0;
    for (size_t k = 0; k < n * n; k++) {
        hb->D[2 * k] = hb->K[k] - w * w * hb->M[k];
        hb->D[2 * k + 1] = w * damping(hb, k);
        dmax = fmax(dmax, fabs(hb->K[k]) + w * w * fabs(hb->M[k]) + fabs(hb->D[2 * k + 1]));
    }
    return dmax;
}

/* Forms and factors D_h in hb->D; FRICREG_ESINGULAR if a pivot is below 1e-14 of the largest
 * entry of |K| + w² |M| + w |C| (or not finite). */
static int factor_one(fricreg_hb *hb, const char *fn, int h, double omega)
{
    size_t n = hb->n;
    double dmax = form_one(hb, h, omega);
    if (!isfinite(dmax))
        return fr_fail(hb, FRICREG_ENONFINITE,
                       "%s: the dynamic stiffness D_%d overflows at Omega = %g (|K| + w^2 |M| + w "
                       "|C| beyond the double range)",
                       fn, h, omega);
    fr_hb_zlu_factor(hb->D, n, hb->piv);
    for (size_t k = 0; k < n; k++) {
        double p = hypot(hb->D[2 * (k * n + k)], hb->D[2 * (k * n + k) + 1]);
        if (!(p > 1e-14 * dmax) || !isfinite(p))
            return fr_fail(hb, FRICREG_ESINGULAR,
                           "%s: %s is singular at Omega = %g (pivot %zu of its LU factor: %g, "
                           "the matrices' scale %g)",
                           fn, h == 0 ? "K" : "the dynamic stiffness D_h", omega, k, p, dmax);
    }
    return FRICREG_OK;
}

/* The 1-norm condition number of the dense D_h at omega, estimated by zgecon from a factor
 * formed again (hb->D holds the last harmonic's only): D_h is symmetric, so its 1-norm is the
 * largest row sum, and zgecon's of the transpose that LAPACK factors is the same. */
static int dense_condition(fricreg_hb *hb, const char *fn, int h, double omega, double *kappa)
{
    size_t n = hb->n;
    form_one(hb, h, omega);
    double norm1 = 0.0;
    for (size_t i = 0; i < n; i++) {
        double sum = 0.0;
        for (size_t j = 0; j < n; j++)
            sum += hypot(hb->D[2 * (i * n + j)], hb->D[2 * (i * n + j) + 1]);
        norm1 = fmax(norm1, sum);
    }
    int status = factor_one(hb, fn, h, omega);
    if (status != FRICREG_OK)
        return status;
    /* Z holds n (m + 1) >= 2 n complex numbers (m >= 1), colw n: zgecon's work and rwork */
    double rcond = fr_hb_zlu_rcond(hb->D, n, norm1, hb->Z, hb->colw);
    *kappa = rcond > 0.0 ? 1.0 / rcond : INFINITY;
    return FRICREG_OK;
}

int fr_hb_condition(fricreg_hb *hb, const char *fn, double *kappa)
{
    double omega = hb->factored_omega;
    *kappa = 0.0;
    for (int h = 0; h <= hb->H && isfinite(omega) && hb->m > 0; h++) { /* m = 0: no (R) */
        double k = 0.0;
        int status = hb->sparse ? fr_hb_sparse_condition(hb, fn, h, omega, &k)
                                : dense_condition(hb, fn, h, omega, &k);
        if (status != FRICREG_OK)
            return status;
        *kappa = fmax(*kappa, k);
    }
    return FRICREG_OK;
}

/* Y_h's columns: D_h^-1 J_e^T for each element e, and D_h^-1 P_h (0 but for h = 1), solved
 * together in the scratch Z (column after column, LAPACK's layout) by one zgetrs: BLAS 3,
 * where one column at a time was BLAS 2 and most of the condensation's time (1.0 of 1.6 s at
 * 696 rows on 859 dofs, docs/hb_size.md). */
static void solve_columns(fricreg_hb *hb, int h)
{
    size_t n = hb->n, m = hb->m, w = m + 1, nrhs = h == 1 ? w : m;
    double *Y = hb->Y + 2 * (size_t)h * n * w, *B = hb->Z;
    for (size_t e = 0; e < nrhs; e++)
        for (size_t k = 0; k < n; k++) {
            B[2 * (e * n + k)] = e < m ? hb->J[e * n + k] : hb->pc[k];
            B[2 * (e * n + k) + 1] = e < m ? 0.0 : -hb->ps[k];
        }
    if (nrhs > 0)
        fr_hb_zlu_solve_many(hb->D, n, hb->piv, nrhs, B);
    for (size_t k = 0; k < n; k++) /* column e of Y_h, row stride w */
        for (size_t e = 0; e < w; e++) {
            Y[2 * (k * w + e)] = e < nrhs ? B[2 * (e * n + k)] : 0.0;
            Y[2 * (k * w + e) + 1] = e < nrhs ? B[2 * (e * n + k) + 1] : 0.0;
        }
}

/* out[e (m+1) + c] (complex, c <= m) = s sum_k L(e, k) B[k (m+1) + c], L(e, k) = J(e, k)
 * (real) when left is NULL, else left[k (m+1) + e] (complex: a column of Y as a row).
 *
 * Row e of the result is accumulated over the k where L(e, k) is not zero, in increasing k,
 * each term added to the whole row (B's row k is contiguous): O(nnz(J) (m + 1)) where J picks
 * the elements' dofs (one non-zero a row), O(m² n) for a dense J or left. The sums are those of
 * the plain triple loop term by term: a zero L adds a signed zero to a sum that starts at +0
 * and is never −0 (a sum that cancels exactly is +0), so leaving it out changes no bit. */
void fr_hb_project(const fricreg_hb *hb, const double *left, const double *B, double s, double *G,
                   double *q)
{
    size_t n = hb->n, m = hb->m, w = m + 1;
    for (size_t e = 0; e < m; e++) {
        double *row = G + 2 * e * m, *last = q + 2 * e; /* c < m, then c = m */
        memset(row, 0, 2 * m * sizeof(double));
        last[0] = last[1] = 0.0;
        for (size_t k = 0; k < n; k++) {
            double lr = left == NULL ? hb->J[e * n + k] : left[2 * (k * w + e)];
            double li = left == NULL ? 0.0 : left[2 * (k * w + e) + 1];
            if (lr == 0.0 && li == 0.0)
                continue;
            const double *b = B + 2 * k * w;
            for (size_t c = 0; c < m; c++)
                cmac(row + 2 * c, s, lr, li, b[2 * c], b[2 * c + 1]);
            cmac(last, s, lr, li, b[2 * m], b[2 * m + 1]);
        }
    }
}

/* z [n] = D_h' y [n] (complex), D_h' = dD_h/dΩ = −2 h² Ω M + i h C_d (C_d the damping in
 * force: c_C C + c_K K + c_M M), by BLAS on y's interleaved parts as a real n × 2 matrix (M, K,
 * C are real and symmetric): z = C_d y, then i h z, then z += −2 h² Ω M y. */
static void derivative_times(fricreg_hb *hb, int h, double omega, const double *y, double *z)
{
    int rows = (int)hb->n, two = 2;
    double cm = -hb->xi, ck = 0.0, cc = 0.0, beta = 0.0, one = 1.0;
    if (!hb->no_c && hb->rayleigh) {
        cm += hb->a0;
        ck = hb->a1;
    } else if (!hb->no_c) {
        cc = 1.0;
    }
    const double *A[3] = {hb->C, hb->K, hb->M}, coef[3] = {cc, ck, cm};
    for (int t = 0; t < 3; t++) {
        if (coef[t] == 0.0)
            continue;
        dgemm_("N", "N", &two, &rows, &rows, &coef[t], y, &two, A[t], &rows, &beta, z, &two, 1, 1);
        beta = 1.0;
    }
    if (beta == 0.0)
        memset(z, 0, 2 * hb->n * sizeof(double));
    for (size_t k = 0; k < hb->n; k++) { /* i h z */
        double re = z[2 * k];
        z[2 * k] = -h * z[2 * k + 1];
        z[2 * k + 1] = h * re;
    }
    double a = -2.0 * h * h * omega;
    dgemm_("N", "N", &two, &rows, &rows, &a, y, &two, hb->M, &rows, &one, z, &two, 1, 1);
}

/* res = −Y_J^T D_h' y (complex, element e at res + e stride doubles, e < m) for y [n]
 * (complex) in hb->Z's first 2n doubles: where y = Y_h c, the Ω derivative of the
 * condensation's product J Y_h c with c [m + 1] (the elements' forces and the load), as
 * dD_h^-1/dΩ = −D_h^-1 D_h' D_h^-1 and J D_h^-1 = Y_J^T (D_h symmetric); hb->Z's next 2n
 * doubles are scratch. */
static void derivative_apply(fricreg_hb *hb, int h, double omega, double *res, size_t stride)
{
    size_t n = hb->n, m = hb->m, w = m + 1;
    const double *Y = hb->Y + 2 * (size_t)h * n * w, *y = hb->Z;
    double *z = hb->Z + 2 * n;
    if (hb->sparse)
        fr_hb_sparse_derivative(hb, h, omega, y, z);
    else
        derivative_times(hb, h, omega, y, z);
    for (size_t e = 0; e < m; e++)
        res[e * stride] = res[e * stride + 1] = 0.0;
    for (size_t k = 0; k < n; k++) /* −Y_J^T z, row k of Y contiguous */
        for (size_t e = 0; e < m; e++)
            cmac(res + e * stride, -1.0, Y[2 * (k * w + e)], Y[2 * (k * w + e) + 1], z[2 * k],
                 z[2 * k + 1]);
}

/* dql_h = −Y_J^T D_h' Y_P (Y_P the last column of Y_h) into dq [m] (complex). */
static void load_derivative(fricreg_hb *hb, int h, double omega, double *dq)
{
    size_t n = hb->n, w = hb->m + 1;
    const double *Y = hb->Y + 2 * (size_t)h * n * w;
    for (size_t k = 0; k < n; k++) {
        hb->Z[2 * k] = Y[2 * (k * w + hb->m)];
        hb->Z[2 * k + 1] = Y[2 * (k * w + hb->m) + 1];
    }
    derivative_apply(hb, h, omega, dq, 2);
}

/* dR/dΩ at harmonic h from y = Y_h c, c = [F_h; −load] (F = fa − i fb, the forces' complex
 * form; derivative_apply takes its derivative), in (R)'s real form:
 * R_a = Re, R_b = −Im of the complex derivative (fr_hb_apply's). */
static void domega_harmonic(fricreg_hb *hb, int h, double *out)
{
    size_t n = hb->n, m = hb->m, w = m + 1, nc = hb->nc, ca = 2 * (size_t)h - 1;
    const double *Y = hb->Y + 2 * (size_t)h * n * w, *f = hb->fq;
    double load = fr_hb_load(hb), *y = hb->Z;
    for (size_t k = 0; k < n; k++) {
        const double *row = Y + 2 * k * w;
        double yr = -load * row[2 * m], yi = -load * row[2 * m + 1];
        for (size_t e = 0; e < m; e++) { /* (gr + i gi)(fa − i fb) */
            double fa = f[e * nc + ca], fb = f[e * nc + ca + 1];
            yr += row[2 * e] * fa + row[2 * e + 1] * fb;
            yi += row[2 * e + 1] * fa - row[2 * e] * fb;
        }
        y[2 * k] = yr;
        y[2 * k + 1] = yi;
    }
    derivative_apply(hb, h, hb->factored_omega, out + ca, nc);
    for (size_t e = 0; e < m; e++)
        out[e * nc + ca + 1] = -out[e * nc + ca + 1];
}

void fr_hb_domega(fricreg_hb *hb, double *out)
{
    for (size_t e = 0; e < hb->m; e++) /* D_0 = K: no Ω */
        out[e * hb->nc] = 0.0;
    for (int h = 1; h <= hb->H; h++)
        domega_harmonic(hb, h, out);
}

/* The solves and the condensation are finite: a model, element or excitation scale near the
 * double range overflows in them (FRICREG_ENONFINITE), before NaN reaches the AFT. */
static int check_finite(fricreg_hb *hb, const char *fn, double omega)
{
    size_t H1 = (size_t)hb->H + 1, m = hb->m;
    size_t counts[3] = {2 * H1 * hb->n * (m + 1), 2 * H1 * m * m, 2 * H1 * m};
    const double *arrays[3] = {hb->Y, hb->G, hb->ql};
    for (int a = 0; a < 3; a++)
        for (size_t k = 0; k < counts[a]; k++)
            if (!isfinite(arrays[a][k]))
                return fr_fail(hb, FRICREG_ENONFINITE,
                               "%s: the solves with D_h overflow at Omega = %g (the model's, the "
                               "elements' or the excitation's scale is near the double range)",
                               fn, omega);
    return FRICREG_OK;
}

int fr_hb_factor(fricreg_hb *hb, const char *fn, double omega, int deriv)
{
    if (hb->factored_omega == omega && (hb->factored_deriv || !deriv))
        return FRICREG_OK;
    size_t n = hb->n, m = hb->m, w = m + 1;
    hb->factored_omega = NAN;
    int status = FRICREG_OK, modal = fr_hb_modal_ready(hb);
    for (int h = 0; h <= hb->H; h++) {
        double *dq = hb->dql + 2 * (size_t)h * m;
        if (deriv && h == 0) /* D_0 = K: its Ω derivative 0 */
            memset(dq, 0, 2 * m * sizeof(double));
        if (h == 0 && !hb->sparse && hb->k_kept == hb->model_serial + 1)
            continue; /* Y_0, G_0 kept */
        double *G = hb->G + 2 * (size_t)h * m * m, *q = hb->ql + 2 * (size_t)h * m;
        if (hb->sparse) {
            status = fr_hb_sparse_solve(hb, fn, h, omega);
        } else if (modal) {
            status = fr_hb_modal_solve(hb, fn, h, omega);
        } else {
            status = factor_one(hb, fn, h, omega);
            if (status == FRICREG_OK)
                solve_columns(hb, h);
        }
        if (status != FRICREG_OK)
            return status;
        fr_hb_project(hb, NULL, hb->Y + 2 * (size_t)h * n * w, 1.0, G, q);
        if (h == 0 && !hb->sparse)
            hb->k_kept = hb->model_serial + 1;
        if (deriv && h > 0)
            load_derivative(hb, h, omega, dq);
    }
    if ((status = check_finite(hb, fn, omega)) != FRICREG_OK)
        return status;
    hb->factored_omega = omega;
    hb->factored_deriv = deriv;
    hb->factor_serial++;
    return FRICREG_OK;
}

int fr_hb_harmonic_solve(fricreg_hb *hb, const char *fn, int h, double omega, size_t nrhs,
                         double *B)
{
    if (hb->sparse)
        return fr_hb_sparse_solve_many(hb, fn, h, omega, nrhs, B);
    int status = factor_one(hb, fn, h, omega);
    for (size_t c = 0; c < nrhs && status == FRICREG_OK; c++)
        fr_hb_zlu_solve_factored(hb->D, hb->n, hb->piv, B + 2 * c * hb->n);
    return status;
}
