/* SPDX-License-Identifier: GPL-3.0-or-later */
/* reduction.c — the linear structure condensed onto the dofs the elements touch (R. R. Craig,
 * M. C. C. Bampton, AIAA J. 6 (1968) 1313), for the condensed stability: with B the dofs some
 * row of J touches and I the others,
 *
 *     x = T (x_B, η),   x_I = Ψ x_B + Φ_k η,   Ψ = −K_II^-1 K_IB,
 *
 * Φ_k the k lowest fixed-interface modes (K_II φ_r = ω_r² M_II φ_r, φ_r^T M_II φ_r = 1). The
 * elements act on x_B alone, which T keeps, so the reduced model T^T M T, T^T C T, T^T K T, J T
 * has the full model's switches along the orbit; what it leaves out are the interior modes above
 * the cut, which answer the harmonics quasi-statically (Ψ holds that answer). Their multipliers
 * are those of the structure's own highest modes (no element: a slider's stiffness hardly moves
 * them), one damped oscillator each, from ω² and the modal damping φ^T C φ (exact for Rayleigh
 * damping); the fixed-interface modes' own were 5e-3 off where damping falls with frequency,
 * the structure's 1.3e-6 (tests/floquet/test_hb_condensed.c). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/free_all.h"
#include "base/fr_math.h"
#include "base/lapack.h"
#include "reduction.h"

struct fr_hb_reduction {
    unsigned long serial; /* the driver's model it was built for */
    size_t n, m, nb, ni, k;
    size_t *bnd, *inr;    /* [nb], [ni] */
    double *w2, *c2;      /* [ni] the interior modes' ω² and modal damping */
    double *w2f, *c2f;    /* [n] the whole structure's modes (no element) */
    double *Phi, *Psi;    /* [ni ni], [ni nb] column-major */
    double *M, *K, *C;    /* the full model [n n] */
    double *T, *work;     /* [n n] each at most (the kept order) */
    double *Mr, *Kr, *Cr; /* [nr nr] */
    double *Jr;           /* [m nr] row-major */
};

void fr_hb_dense_model(const fricreg_hb *hb, double *M, double *C, double *K)
{
    size_t n = hb->n;
    if (!hb->sparse) {
        memcpy(M, hb->M, n * n * sizeof(double));
        memcpy(K, hb->K, n * n * sizeof(double));
        for (size_t i = 0; i < n * n; i++)
            C[i] = hb->rayleigh ? hb->a0 * hb->M[i] + hb->a1 * hb->K[i] : hb->C[i];
        return;
    }
    memset(M, 0, n * n * sizeof(double));
    memset(K, 0, n * n * sizeof(double));
    memset(C, 0, n * n * sizeof(double));
    for (size_t l = 0; l < n; l++)
        for (int64_t p = hb->Dp[l]; p < hb->Dp[l + 1]; p++) {
            size_t i = (size_t)hb->Di[p] + l * n;
            M[i] = hb->vM[p];
            K[i] = hb->vK[p];
            C[i] = hb->rayleigh ? hb->a0 * hb->vM[p] + hb->a1 * hb->vK[p] : hb->vC[p];
        }
}

static int touched(const fricreg_hb *hb, size_t l)
{
    for (size_t r = 0; r < hb->m; r++)
        if (hb->J[r * hb->n + l] != 0.0)
            return 1;
    return 0;
}

size_t fr_hb_boundary_dofs(const fricreg_hb *hb)
{
    size_t nb = 0;
    for (size_t l = 0; l < hb->n; l++)
        nb += (size_t)touched(hb, l);
    return nb;
}

void fr_hb_reduction_free(fricreg_hb *hb)
{
    struct fr_hb_reduction *r = hb->stability->reduction;
    if (r == NULL)
        return;
    FR_FREE_ALL(r->bnd, r->w2);
    free(r);
    hb->stability->reduction = NULL;
}

/* Block (rows, cols) of the full column-major A [n n] into out [nr nc] column-major. */
static void block(const double *A, size_t n, const size_t *rows, size_t nr, const size_t *cols,
                  size_t nc, double *out)
{
    for (size_t j = 0; j < nc; j++)
        for (size_t i = 0; i < nr; i++)
            out[j * nr + i] = A[cols[j] * n + rows[i]];
}

/* The modes of (K, M) of order N, K [N N] overwritten by them (M-orthonormal), M destroyed, with
 * their ω² into w2 [N] and modal damping φ^T C φ into c2 [N], C [N N], CPhi [N N] scratch.
 * LAPACK's dsygvd's INFO, or −1 without memory for its workspace. */
static int modal_data(size_t n, double *K, double *M, const double *C, double *CPhi, double *w2,
                      double *c2)
{
    int N = (int)n, one = 1, lwork = -1, liwork = -1, iq = 0, info = 0;
    double wq = 0.0, one_d = 1.0, zero = 0.0;
    dsygvd_(&one, "V", "L", &N, K, &N, M, &N, w2, &wq, &lwork, &iq, &liwork, &info, 1, 1);
    lwork = (int)wq;
    liwork = iq;
    double *work = malloc(((size_t)lwork + (size_t)liwork) * sizeof(double));
    if (work == NULL)
        return -1;
    dsygvd_(&one, "V", "L", &N, K, &N, M, &N, w2, work, &lwork, (int *)(work + lwork), &liwork,
            &info, 1, 1);
    free(work);
    if (info != 0)
        return info;
    dgemm_("N", "N", &N, &N, &N, &one_d, C, &N, K, &N, &zero, CPhi, &N, 1, 1);
    for (size_t j = 0; j < n; j++) {
        double c = 0.0;
        for (size_t i = 0; i < n; i++)
            c += K[j * n + i] * CPhi[j * n + i];
        c2[j] = c;
    }
    return 0;
}

static int modes_failed(fricreg_hb *hb, const char *fn, const char *which, int info)
{
    if (info < 0)
        return fr_fail(hb, FRICREG_ENOMEM, "%s: stability: no memory for the %s modes", fn, which);
    return fr_fail(hb, FRICREG_ESINGULAR,
                   "%s: stability: LAPACK's dsygvd failed on the %s modes (INFO %d)", fn, which,
                   info);
}

/* The boundary, Ψ, every interior mode and every mode of the whole structure, each with its ω²
 * and modal damping; T, work, Mr and Kr are scratch [n n] until the model is reduced. */
static int modes(fricreg_hb *hb, const char *fn, struct fr_hb_reduction *r)
{
    size_t n = r->n, nb = r->nb, ni = r->ni;
    for (size_t l = 0, b = 0, i = 0; l < n; l++)
        if (touched(hb, l))
            r->bnd[b++] = l;
        else
            r->inr[i++] = l;
    fr_hb_dense_model(hb, r->M, r->C, r->K);
    memcpy(r->T, r->K, n * n * sizeof(double));
    memcpy(r->work, r->M, n * n * sizeof(double));
    int info = modal_data(n, r->T, r->work, r->C, r->Mr, r->w2f, r->c2f);
    if (info != 0)
        return modes_failed(hb, fn, "structure's", info);
    if (ni == 0)
        return FRICREG_OK;
    double *Kii = r->T; /* K_II's Cholesky factor for Ψ */
    int N = (int)ni, NB = (int)nb;
    block(r->K, n, r->inr, ni, r->inr, ni, Kii);
    block(r->K, n, r->inr, ni, r->bnd, nb, r->Psi);
    dpotrf_("L", &N, Kii, &N, &info, 1);
    if (info == 0 && nb > 0) {
        dpotrs_("L", &N, &NB, Kii, &N, r->Psi, &N, &info, 1);
        for (size_t i = 0; i < ni * nb; i++)
            r->Psi[i] = -r->Psi[i];
    }
    if (info != 0)
        return fr_fail(hb, FRICREG_ESINGULAR,
                       "%s: stability: the stiffness of the dofs no element touches is not "
                       "positive definite (the condensed method needs it): choose "
                       "FRICREG_HB_STABILITY_MONODROMY",
                       fn);
    block(r->K, n, r->inr, ni, r->inr, ni, r->Phi);
    block(r->M, n, r->inr, ni, r->inr, ni, r->work);
    block(r->C, n, r->inr, ni, r->inr, ni, r->Kr);
    info = modal_data(ni, r->Phi, r->work, r->Kr, r->Mr, r->w2, r->c2);
    return info == 0 ? FRICREG_OK : modes_failed(hb, fn, "interior", info);
}

/* B^T A B for A [n n] and B [n nr], column-major, into out [nr nr]. */
static void congruence(const struct fr_hb_reduction *r, const double *A, size_t nr, double *out)
{
    int N = (int)r->n, NR = (int)nr;
    double one = 1.0, zero = 0.0;
    dgemm_("N", "N", &N, &NR, &N, &one, A, &N, r->T, &N, &zero, r->work, &N, 1, 1);
    dgemm_("T", "N", &NR, &NR, &N, &one, r->T, &N, r->work, &N, &zero, out, &NR, 1, 1);
}

/* T and the reduced model for the k lowest interior modes. */
static void reduce(const fricreg_hb *hb, struct fr_hb_reduction *r, size_t k)
{
    size_t n = r->n, nb = r->nb, ni = r->ni, nr = nb + k;
    memset(r->T, 0, n * nr * sizeof(double));
    for (size_t j = 0; j < nb; j++) {
        r->T[j * n + r->bnd[j]] = 1.0;
        for (size_t i = 0; i < ni; i++)
            r->T[j * n + r->inr[i]] = r->Psi[j * ni + i];
    }
    for (size_t q = 0; q < k; q++)
        for (size_t i = 0; i < ni; i++)
            r->T[(nb + q) * n + r->inr[i]] = r->Phi[q * ni + i];
    congruence(r, r->M, nr, r->Mr);
    congruence(r, r->K, nr, r->Kr);
    congruence(r, r->C, nr, r->Cr);
    for (size_t row = 0; row < hb->m; row++) /* J T: row by row */
        for (size_t c = 0; c < nr; c++) {
            double s = 0.0;
            for (size_t l = 0; l < n; l++)
                s += hb->J[row * n + l] * r->T[c * n + l];
            r->Jr[row * nr + c] = s;
        }
    r->k = k;
}

static struct fr_hb_reduction *reduction_new(const fricreg_hb *hb, size_t nb)
{
    size_t n = hb->n, ni = n - nb, m = hb->m;
    struct fr_hb_reduction *r = calloc(1, sizeof *r);
    if (r == NULL)
        return NULL;
    *r = (struct fr_hb_reduction){
        .serial = hb->model_serial, .n = n, .m = m, .nb = nb, .ni = ni, .k = (size_t)-1};
    r->bnd = malloc((n + 1) * sizeof *r->bnd);
    r->w2 = malloc((2 * ni + 2 * n + ni * ni + ni * nb + 8 * n * n + m * n + 1) * sizeof(double));
    if (r->bnd == NULL || r->w2 == NULL) {
        FR_FREE_ALL(r->bnd, r->w2);
        free(r);
        return NULL;
    }
    r->inr = r->bnd + nb;
    r->c2 = r->w2 + ni;
    r->w2f = r->c2 + ni;
    r->c2f = r->w2f + n;
    r->Phi = r->c2f + n;
    r->Psi = r->Phi + ni * ni;
    r->M = r->Psi + ni * nb; /* M, K, C, T, work, Mr, Kr, Cr: [n n] each at most */
    r->K = r->M + n * n;
    r->C = r->K + n * n;
    r->T = r->C + n * n;
    r->work = r->T + n * n;
    r->Mr = r->work + n * n;
    r->Kr = r->Mr + n * n;
    r->Cr = r->Kr + n * n;
    r->Jr = r->Cr + n * n;
    return r;
}

int fr_hb_reduction_update(fricreg_hb *hb, const char *fn, double omega,
                           struct fr_hb_linear_model *out)
{
    struct fr_hb_reduction *r = hb->stability->reduction;
    if (r != NULL && (r->serial != hb->model_serial || r->n != hb->n || r->m != hb->m)) {
        fr_hb_reduction_free(hb); /* built for another model */
        r = NULL;
    }
    if (r == NULL) {
        size_t nb = fr_hb_boundary_dofs(hb);
        if (hb->n > FR_HB_REDUCTION_MAX_DOFS)
            return fr_fail(hb, FRICREG_EINVAL,
                           "%s: stability: %zu dofs, the condensed method takes %d at most (its "
                           "model and modes are dense)",
                           fn, hb->n, FR_HB_REDUCTION_MAX_DOFS);
        if ((r = reduction_new(hb, nb)) == NULL)
            return fr_fail(hb, FRICREG_ENOMEM,
                           "%s: stability: no memory for the condensed model of %zu dofs", fn,
                           hb->n);
        hb->stability->reduction = r;
        int status = modes(hb, fn, r);
        if (status != FRICREG_OK) {
            fr_hb_reduction_free(hb);
            return status;
        }
    }
    double cut = FR_HB_REDUCTION_CUT * omega;
    size_t k = 0;
    while (k < r->ni && r->w2[k] < cut * cut)
        k++;
    if (k != r->k)
        reduce(hb, r, k);
    *out =
        (struct fr_hb_linear_model){.n = r->nb + k, .M = r->Mr, .K = r->Kr, .C = r->Cr, .J = r->Jr};
    return FRICREG_OK;
}

/* exp(λ T) as an exponent (Re λ, Im λ reduced into (−Ω/2, Ω/2]) into e[2]. */
static void exponent(double re, double im, double T, double *e)
{
    e[0] = re;
    e[1] = atan2(sin(im * T), cos(im * T)) / T;
}

size_t fr_hb_reduction_truncated(const fricreg_hb *hb, double omega, double *exps)
{
    const struct fr_hb_reduction *r = hb->stability->reduction;
    double T = FR_TWO_PI / omega;
    size_t count = 0;
    for (size_t q = r->nb + r->k; q < r->n; q++) { /* λ² + c λ + ω² = 0 */
        double c = r->c2f[q], disc = 0.25 * c * c - r->w2f[q];
        if (disc < 0.0) {
            exponent(-0.5 * c, sqrt(-disc), T, exps + 2 * count++);
            exponent(-0.5 * c, -sqrt(-disc), T, exps + 2 * count++);
        } else {
            exponent(-0.5 * c + sqrt(disc), 0.0, T, exps + 2 * count++);
            exponent(-0.5 * c - sqrt(disc), 0.0, T, exps + 2 * count++);
        }
    }
    return count;
}
