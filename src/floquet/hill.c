/* SPDX-License-Identifier: GPL-3.0-or-later */
/* hill.c — the stability of a periodic solution by Hill's method (G. W. Hill 1886; Krack &
 * Gross 2019, Sec. 5.3; L. Peletan et al., Nonlinear Dyn. 2013): a perturbation
 * y(t) = e^{λt} p(t), p periodic with the real Fourier coefficients P (the layout of fricreg_hb.h,
 * dof k's at P[nc k ..]), of M x'' + C x' + K x + J^T f(J x) = p(t) solves the quadratic
 * eigenproblem
 *
 *     (λ² Δ2 + λ Δ1 + S) P = 0,   Δ2 = M ⊗ I,   Δ1 = C ⊗ I + 2 M ⊗ ∇,                      (Q)
 *
 * S the Jacobian of the full (not condensed) HB equations, K ⊗ I + C ⊗ Ω∇ + M ⊗ Ω²∇² +
 * J^T (∂F/∂q) J with the elements' exact AFT Jacobians ∂F/∂q, and ∇ the derivative of one
 * period's coefficients (a_h' = hΩ b_h, b_h' = −hΩ a_h; Ω folded into ∇ in Δ1). (Q) is solved
 * as the eigenproblem of its companion matrix [0 I; −Δ2⁻¹ S, −Δ2⁻¹ Δ1] of order 2N, N = n nc, by
 * LAPACK's dgeev (eigenvalues.c: balancing, Hessenberg reduction, multishift QR). Its 2N
 * eigenvalues hold each Floquet exponent λ many times over, λ + i k Ω, the truncation's error
 * growing with |k|: the 2n of least |Im λ| (those within ±Ω/2, the imaginary-part criterion of
 * Krack & Gross, Sec. 5.3.3) are taken as the exponents, the multipliers μ = e^{λ T}, T = 2π/Ω.
 * A solution is stable when every exponent has Re λ T <= 1e-6 (|μ| <= 1 + 1e-6).
 *
 * The elements' stabilized hysteresis enters through its HB Jacobian, as in NLvib's Hill's
 * method: the sliders' offsets, forgotten once they slip, are no state of their own here. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "base/gsl_mem.h"
#include "floquet_internal.h"
#include "hb/lu.h"
#include "base/free_all.h"

static const double TWO_PI = 6.283185307179586;

int fr_hb_hill_reserve(fricreg_hb *hb, const char *fn)
{
    size_t n = hb->n, N2 = 2 * n * hb->nc;
    if (hb->stability->hill != NULL)
        return FRICREG_OK;
    struct fr_hb_hill *w = calloc(1, sizeof *w);
    if (w != NULL) {
        w->A = fr_gsl_matrix_new(N2, N2);
        w->eval = malloc(2 * N2 * sizeof(double));
        w->lwork = fr_hb_eigenvalues_work(N2);
        w->work = malloc((w->lwork + 2 * N2) * sizeof(double));
        w->mlu = malloc((n * n + n) * sizeof(double));
        w->piv = malloc(n * sizeof *w->piv);
    }
    hb->stability->hill = w;
    if (!w || !w->A || !w->eval || !w->work || !w->mlu || !w->piv) {
        fr_hb_hill_free(hb);
        return fr_fail(hb, FRICREG_ENOMEM,
                       "%s: stability: no memory for Hill's matrix of order %zu", fn, N2);
    }
    w->col = w->mlu + n * n;
    return FRICREG_OK;
}

void fr_hb_hill_free(fricreg_hb *hb)
{
    struct fr_hb_hill *w = hb->stability->hill;
    if (w == NULL)
        return;
    free(w->A); /* one block (gsl_mem.h) */
    FR_FREE_ALL(w->eval, w->work, w->mlu, w->piv, w);
    hb->stability->hill = NULL;
}

/* The dense model's damping entry: C, or a0 M + a1 K. */
static double damping(const fricreg_hb *hb, size_t idx)
{
    return hb->rayleigh ? hb->a0 * hb->M[idx] + hb->a1 * hb->K[idx] : hb->C[idx];
}

/* The linear parts of S and Δ1 of (Q) for dofs k, l (M, C, K entries m, c, kk) into the
 * companion's lower blocks (rows N.., columns 0.. and N..): for harmonic h, with w = hΩ, on
 * (a_h, b_h): S = [K − w² M, w C; −w C, K − w² M], Δ1 = [C, 2 w M; −2 w M, C]; h = 0: S = K,
 * Δ1 = C. */
static void linear_entry(fricreg_hb *hb, double omega, size_t k, size_t l, double m, double c,
                         double kk)
{
    size_t nc = hb->nc, N = hb->n * nc, r = N + k * nc, col = l * nc;
    gsl_matrix *A = hb->stability->hill->A;
    *gsl_matrix_ptr(A, r, col) += kk;
    *gsl_matrix_ptr(A, r, N + col) += c;
    for (int h = 1; h <= hb->H; h++) {
        size_t a = 2 * (size_t)h - 1, b = a + 1;
        double w = h * omega, kd = kk - w * w * m;
        *gsl_matrix_ptr(A, r + a, col + a) += kd;
        *gsl_matrix_ptr(A, r + a, col + b) += w * c;
        *gsl_matrix_ptr(A, r + b, col + b) += kd;
        *gsl_matrix_ptr(A, r + b, col + a) -= w * c;
        *gsl_matrix_ptr(A, r + a, N + col + a) += c;
        *gsl_matrix_ptr(A, r + a, N + col + b) += 2.0 * w * m;
        *gsl_matrix_ptr(A, r + b, N + col + b) += c;
        *gsl_matrix_ptr(A, r + b, N + col + a) -= 2.0 * w * m;
    }
}

/* Every entry of M, C, K (the dense arrays, or the sparse pattern of D_h with both triangles,
 * sparse.c) through linear_entry, and M itself into hill_mlu [n n]. */
static void linear_blocks(fricreg_hb *hb, double omega)
{
    size_t n = hb->n;
    if (!hb->sparse) {
        for (size_t k = 0; k < n; k++)
            for (size_t l = 0; l < n; l++) {
                size_t i = k * n + l;
                linear_entry(hb, omega, k, l, hb->M[i], damping(hb, i), hb->K[i]);
                hb->stability->hill->mlu[i] = hb->M[i];
            }
        return;
    }
    memset(hb->stability->hill->mlu, 0, n * n * sizeof(double));
    for (size_t l = 0; l < n; l++)
        for (int64_t p = hb->Dp[l]; p < hb->Dp[l + 1]; p++) {
            size_t k = (size_t)hb->Di[p];
            double c = hb->rayleigh ? hb->a0 * hb->vM[p] + hb->a1 * hb->vK[p] : hb->vC[p];
            linear_entry(hb, omega, k, l, hb->vM[p], c, hb->vK[p]);
            hb->stability->hill->mlu[k * n + l] = hb->vM[p];
        }
}

/* J^T (∂F/∂q) J added to S: element e's Jacobian block (rows s nc + c, columns s2 nc + c2 of
 * its rows) between J's rows erow[e] + s and erow[e] + s2. */
static void element_blocks(fricreg_hb *hb)
{
    size_t n = hb->n, nc = hb->nc, N = n * nc;
    gsl_matrix *A = hb->stability->hill->A;
    for (size_t e = 0; e < hb->me; e++) {
        size_t rows = fr_hb_rows_of(hb, e), b = rows * nc, r0 = hb->erow[e];
        const double *block = fr_hb_block_of(hb, e);
        for (size_t s = 0; s < rows; s++)
            for (size_t s2 = 0; s2 < rows; s2++) {
                const double *Jr = hb->J + (r0 + s) * n, *Jr2 = hb->J + (r0 + s2) * n;
                for (size_t c = 0; c < nc; c++)
                    for (size_t c2 = 0; c2 < nc; c2++) {
                        double v = block[(s * nc + c) * b + s2 * nc + c2];
                        if (v == 0.0)
                            continue;
                        for (size_t k = 0; k < n; k++)
                            for (size_t l = 0; l < n; l++)
                                if (Jr[k] != 0.0 && Jr2[l] != 0.0)
                                    *gsl_matrix_ptr(A, N + k * nc + c, l * nc + c2) += Jr[k] * v *
                                                                                       Jr2[l];
                    }
            }
    }
}

/* The lower blocks times −Δ2⁻¹ = −M⁻¹ ⊗ I (M's LU, checked), and the identity above. */
static int companion(fricreg_hb *hb, const char *fn)
{
    size_t n = hb->n, nc = hb->nc, N = n * nc;
    gsl_matrix *A = hb->stability->hill->A;
    /* hill_mlu holds M (linear_blocks) */
    int status = fr_hb_mass_lu(hb, fn, "Hill's method", hb->n, hb->stability->hill->mlu,
                               hb->stability->hill->piv);
    if (status != FRICREG_OK)
        return status;
    for (size_t j = 0; j < 2 * N; j++)
        for (size_t c = 0; c < nc; c++) {
            for (size_t k = 0; k < n; k++)
                hb->stability->hill->col[k] = gsl_matrix_get(A, N + k * nc + c, j);
            fr_hb_lu_solve_factored(hb->stability->hill->mlu, n, hb->stability->hill->piv,
                                    hb->stability->hill->col);
            for (size_t k = 0; k < n; k++)
                gsl_matrix_set(A, N + k * nc + c, j, -hb->stability->hill->col[k]);
        }
    for (size_t j = 0; j < N; j++)
        gsl_matrix_set(A, j, N + j, 1.0);
    return FRICREG_OK;
}

/* An eigenvalue's place in the selection: |Im λ|, except that on the line |Im λ| = Ω/2 (to
 * 1e-6 of Ω) the conjugate with Im λ < 0 comes after every one with Im λ > 0 of the line. A real
 * negative multiplier μ = −e^{rT} appears there as the conjugates r ± iΩ/2; two of them (as
 * after a pair's collision on the negative real axis: det Φ > 0 makes them come in pairs) give
 * four eigenvalues of one |Im λ|, and by |Im λ| alone the tie could take the smaller multiplier
 * twice and drop the larger (measured: |μ| 0.36 for the shooting's 2.54 on a bilinear
 * oscillator). Each multiplier is then taken once, its Im λ > 0 representative. */
static double selection_key(double im, double omega, int *second)
{
    double a = fabs(im);
    /* the line only: above it, the copies λ + i k Ω keep their |Im λ| (1.7 put them all on
     * the line, and GSL's order of the eigenvalues hid it; LAPACK's order took copies at
     * |Im λ| = 15.8 Ω/2 for a period doubling's exponents on a bilinear oscillator) */
    int on_line = fabs(a - 0.5 * omega) <= 1e-6 * omega;
    *second = on_line && im < 0.0;
    return on_line ? 0.5 * omega : a;
}

/* The 2n eigenvalues of least selection_key (a selection, out of place) as (re, im) into
 * out[4n]: ties (conjugates, a real pair) in index order. */
static void select_exponents(const fricreg_hb *hb, double omega, double *out)
{
    size_t N2 = 2 * hb->n * hb->nc, want = 2 * hb->n;
    const double *ev = hb->stability->hill->eval;
    double last = -1.0;
    int last_second = 0;
    size_t last_at = 0;
    for (size_t i = 0; i < want; i++) {
        /* the next by (key, second, index) */
        size_t best = N2;
        double best_a = 0.0;
        int best_second = 0;
        for (size_t j = 0; j < N2; j++) {
            int second;
            double a = selection_key(ev[2 * j + 1], omega, &second);
            if (a < last ||
                (a == last && (second < last_second || (second == last_second && j <= last_at))))
                continue;
            if (best == N2 || a < best_a || (a == best_a && second < best_second))
                best = j, best_a = a, best_second = second;
        }
        out[2 * i] = ev[2 * best];
        out[2 * i + 1] = ev[2 * best + 1];
        last = best_a;
        last_second = best_second;
        last_at = best;
    }
}

int fr_hb_hill(fricreg_hb *hb, const char *fn, double omega, double *out)
{
    size_t N2 = 2 * hb->n * hb->nc;
    if (hb->n * hb->nc > FRICREG_HB_MAX_HILL)
        return fr_fail(hb, FRICREG_EINVAL,
                       "%s: stability: ndof (2H + 1) = %zu, Hill's method is limited to %d "
                       "coefficients (the exact monodromy is not: piecewise-linear elements)",
                       fn, hb->n * hb->nc, FRICREG_HB_MAX_HILL);
    int status = fr_hb_hill_reserve(hb, fn);
    if (status != FRICREG_OK)
        return status;
    gsl_matrix_set_zero(hb->stability->hill->A);
    linear_blocks(hb, omega);
    element_blocks(hb);
    status = companion(hb, fn);
    if (status != FRICREG_OK)
        return status;
    for (size_t k = 0; k < N2 * N2; k++)
        if (!isfinite(hb->stability->hill->A->data[k]))
            return fr_fail(hb, FRICREG_ENONFINITE,
                           "%s: stability: Hill's matrix overflows at Omega = %g", fn, omega);
    double *wr = hb->stability->hill->work + hb->stability->hill->lwork, *wi = wr + N2;
    if (fr_hb_eigenvalues(hb->stability->hill->A->data, N2, wr, wi, hb->stability->hill->work,
                          hb->stability->hill->lwork) != 0)
        return fr_fail(hb, FRICREG_EINTEGRATOR,
                       "%s: stability: the QR iteration on Hill's matrix did not converge at "
                       "Omega = %g",
                       fn, omega);
    for (size_t i = 0; i < N2; i++) { /* (re, im) pairs, as select_exponents reads them */
        hb->stability->hill->eval[2 * i] = wr[i];
        hb->stability->hill->eval[2 * i + 1] = wi[i];
    }
    select_exponents(hb, omega, out + 2);
    double T = TWO_PI / omega, top = -INFINITY;
    for (size_t i = 0; i < 2 * hb->n; i++)
        top = fmax(top, out[2 + 2 * i] * T);
    out[0] = top <= FR_HB_STABLE_TOL ? 1.0 : 0.0;
    out[1] = exp(top);
    return FRICREG_OK;
}

/* An exponent's kind: 0 real (a multiplier crossing +1: a fold or branch point), 1 at ±Ω/2 (a
 * real negative multiplier: period doubling), 2 complex (Neimark–Sacker), to 1e-6 of Ω. */
static int kind(double im, double omega)
{
    double a = fabs(im);
    return a <= 1e-6 * omega ? 0 : a >= (0.5 - 1e-6) * omega ? 1 : 2;
}

int fr_hb_hill_unstable(const fricreg_hb *hb, double omega, const double *exps, int which)
{
    /* the unit circle itself, not the verdict's margin: a bisection on the margin would stop
     * 1e-6 / (d log|mu|/dOmega) past the crossing (3e-6 rad/s at the gap pair's upper NS) */
    for (size_t i = 0; i < 2 * hb->n; i++)
        if ((which < 0 || kind(exps[2 * i + 1], omega) == which) && exps[2 * i] > 0.0)
            return 1;
    return 0;
}

int fr_hb_hill_crossing(const fricreg_hb *hb, double omega, const double *exps)
{
    size_t top = 0;
    for (size_t i = 1; i < 2 * hb->n; i++)
        if (exps[2 * i] > exps[2 * top])
            top = i;
    return kind(exps[2 * top + 1], omega);
}
