/* SPDX-License-Identifier: GPL-3.0-or-later */
/* monodromy.c — the Floquet multipliers of a periodic HB solution from the exact monodromy of
 * its orbit, for elements that are piecewise linear (R. I. Leine, H. Nijmeijer, Dynamics and
 * Bifurcations of Non-Smooth Mechanical Systems, Springer 2004, Ch. 7: saltation matrices).
 *
 * With 1-D Jenkins and Iwan sliders under a constant normal load, M x'' + C x' + K x + J^T f =
 * p(t) is linear between the sliders' switches, which the exact AFT locates on the solution's
 * q(t) = J x(t) (joint/aft_slips.h). A perturbation z = (δx, δv, δw), δw the offsets of the
 * sliders that switch, follows z' = A_k z on each piece k:
 *
 *     δx' = δv,   M δv' = −C δv − (K + Σ_stuck k_s J_e^T J_e) δx + Σ_stuck k_s J_e^T δw_s,
 *     δw_s' = J_e δv while slider s (of element e) slips, 0 while it sticks,
 *
 * a slipping slider's force ±φ_s being fixed. At a slip onset the perturbed orbit switches when
 * its own force reaches the bound, so its offset then follows q: the saltation δw_s ← J_e δx (x
 * and v stay continuous, as f does); at a stop (q' = 0) nothing jumps. Hence
 *
 *     Φ = e^{A_K Δt_K} S_K ⋯ S_1 e^{A_1 Δt_1},   Δt_k the pieces of θ = Ω t over [0, 2π),    (Φ)
 *
 * each exponential by expm.c. A slider stuck over the whole period keeps a constant offset: its
 * multiplier is a neutral 1 (like HB's offset ambiguity), so it stays out of z, its stiffness
 * in K; one that slips throughout (or has no bound) exerts a fixed force and stays out too.
 * Each slider in z forgets its offset at its onsets, which gives Φ one zero multiplier per
 * such slider: as many of the smallest |μ| are dropped, and the 2n left are the multipliers,
 * λ = log μ / T (Im λ in (−Ω/2, Ω/2]) the exponents, in the layout of Hill's (stability.c). */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/fr_math.h"
#include "expm.h"
#include "joint/aft_slips.h"
#include "monodromy.h"

/* One switch of a slider in z: its angle, the slider's place among z's sliders, onset or stop. */
struct switch_event {
    double theta;
    size_t slider;
    int onset;
};

/* The workspace, sized for n dofs, S sliders and H harmonics; column-major matrices of the
 * order P = 2n + S at most. */
struct fr_hb_mono {
    size_t n, S, P, me;
    int H;
    double *Mlu, *MiK, *MiC, *MiJ; /* [n n] each, MiJ [n me]: M's LU, M^-1 K, M^-1 C, M^-1 J^T */
    double *A, *E, *Phi, *T, *expm_work; /* [P P] each, expm's [6 P P] */
    double *eig_work, *wr, *wi;          /* [lwork], [P], [P] */
    size_t lwork;
    double *on, *off;            /* [2H] one slider's slip intervals */
    double *k;                   /* [S] the stiffness of each slider in z */
    size_t *element;             /* [S] its element */
    int *slipping;               /* [S] whether it slips now */
    int *piv;                    /* [P] */
    struct switch_event *events; /* [2 S 2H] */
};

void fr_hb_monodromy_free(fricreg_hb *hb)
{
    struct fr_hb_mono *w = hb->mono;
    if (w == NULL)
        return;
    free(w->Mlu);
    free(w->eig_work);
    free(w->element);
    free(w->slipping);
    free(w->piv);
    free(w->events);
    free(w);
    hb->mono = NULL;
}

int fr_hb_monodromy_reserve(fricreg_hb *hb, const char *fn)
{
    size_t n = hb->n, me = hb->me, S = hb->me * hb->ns, P = 2 * n + S, H2 = 2 * (size_t)hb->H;
    struct fr_hb_mono *w = hb->mono;
    if (w != NULL && w->n == n && w->me == me && w->S >= S && w->H == hb->H)
        return FRICREG_OK;
    fr_hb_monodromy_free(hb);
    w = calloc(1, sizeof *w);
    size_t lwork = fr_hb_eigenvalues_work(P), mats = 3 * n * n + n * me + 10 * P * P;
    if (w != NULL) {
        w->Mlu = malloc((mats + 2 * H2) * sizeof(double));
        w->eig_work = malloc((lwork + 2 * P + S + 1) * sizeof(double));
        w->element = malloc((S + 1) * sizeof *w->element);
        w->slipping = malloc((S + 1) * sizeof *w->slipping);
        w->piv = malloc(P * sizeof *w->piv);
        w->events = malloc((2 * S * H2 + 1) * sizeof *w->events);
    }
    hb->mono = w;
    if (w == NULL || !w->Mlu || !w->eig_work || !w->element || !w->slipping || !w->piv ||
        !w->events) {
        fr_hb_monodromy_free(hb);
        return fr_fail(hb, FRICREG_ENOMEM,
                       "%s: stability: no memory for the monodromy of order %zu", fn, P);
    }
    *w = (struct fr_hb_mono){.n = n,
                             .S = S,
                             .P = P,
                             .me = me,
                             .H = hb->H,
                             .lwork = lwork,
                             .Mlu = w->Mlu,
                             .eig_work = w->eig_work,
                             .element = w->element,
                             .slipping = w->slipping,
                             .piv = w->piv,
                             .events = w->events};
    w->MiK = w->Mlu + n * n;
    w->MiC = w->MiK + n * n;
    w->MiJ = w->MiC + n * n;
    w->A = w->MiJ + n * me;
    w->E = w->A + P * P;
    w->Phi = w->E + P * P;
    w->T = w->Phi + P * P;
    w->expm_work = w->T + P * P;
    w->on = w->expm_work + fr_hb_expm_work(P);
    w->off = w->on + H2;
    w->wr = w->eig_work + lwork;
    w->wi = w->wr + P;
    w->k = w->wi + P;
    return FRICREG_OK;
}

int fr_hb_monodromy_applies(const fricreg_hb *hb)
{
    return hb->have_elements && hb->rpe == 1 && hb->nl == NULL;
}

/* The model's M, C (or Rayleigh's a0 M + a1 K) and K into Mlu, MiC, MiK, dense (symmetric:
 * row- and column-major alike), from the dense arrays or the sparse pattern of D_h. */
static void dense_model(const fricreg_hb *hb, struct fr_hb_mono *w)
{
    size_t n = hb->n;
    if (!hb->sparse) {
        memcpy(w->Mlu, hb->M, n * n * sizeof(double));
        memcpy(w->MiK, hb->K, n * n * sizeof(double));
        for (size_t i = 0; i < n * n; i++)
            w->MiC[i] = hb->rayleigh ? hb->a0 * hb->M[i] + hb->a1 * hb->K[i] : hb->C[i];
        return;
    }
    memset(w->Mlu, 0, 3 * n * n * sizeof(double));
    for (size_t l = 0; l < n; l++)
        for (int64_t p = hb->Dp[l]; p < hb->Dp[l + 1]; p++) {
            size_t i = (size_t)hb->Di[p] + l * n;
            w->Mlu[i] = hb->vM[p];
            w->MiK[i] = hb->vK[p];
            w->MiC[i] = hb->rayleigh ? hb->a0 * hb->vM[p] + hb->a1 * hb->vK[p] : hb->vC[p];
        }
}

/* M^-1 K, M^-1 C in place and M^-1 J^T into MiJ, by M's LU (its pivots checked as Hill's). */
static int mass_solves(fricreg_hb *hb, const char *fn, struct fr_hb_mono *w)
{
    size_t n = hb->n;
    double mmax = 0.0;
    for (size_t i = 0; i < n * n; i++)
        mmax = fmax(mmax, fabs(w->Mlu[i]));
    fr_hb_lu_factor(w->Mlu, n, w->piv);
    for (size_t k = 0; k < n; k++)
        if (!(fabs(w->Mlu[k * n + k]) > 1e-14 * mmax))
            return fr_fail(hb, FRICREG_ESINGULAR,
                           "%s: stability: the mass matrix is singular (pivot %zu of its LU "
                           "factor: %g, largest entry %g): the monodromy needs M^-1",
                           fn, k, w->Mlu[k * n + k], mmax);
    for (size_t l = 0; l < n; l++) { /* columns; K, C symmetric */
        fr_hb_lu_solve_factored(w->Mlu, n, w->piv, w->MiK + l * n);
        fr_hb_lu_solve_factored(w->Mlu, n, w->piv, w->MiC + l * n);
    }
    for (size_t e = 0; e < hb->me; e++) {
        memcpy(w->MiJ + e * n, hb->J + e * n, n * sizeof(double));
        fr_hb_lu_solve_factored(w->Mlu, n, w->piv, w->MiJ + e * n);
    }
    return FRICREG_OK;
}

/* K += k J_e^T J_e in M^-1's image: MiK += k (M^-1 J_e^T) J_e. */
static void add_stuck_stiffness(const fricreg_hb *hb, struct fr_hb_mono *w, size_t e, double k)
{
    size_t n = hb->n;
    const double *Je = hb->J + e * n, *mj = w->MiJ + e * n;
    for (size_t l = 0; l < n; l++)
        if (Je[l] != 0.0)
            for (size_t i = 0; i < n; i++)
                w->MiK[l * n + i] += k * Je[l] * mj[i];
}

static int by_angle(const void *x, const void *y)
{
    double a = ((const struct switch_event *)x)->theta, b = ((const struct switch_event *)y)->theta;
    return (a > b) - (a < b);
}

/* Every slider's slip intervals on q at the solution: the ones stuck all period into MiK, the
 * ones that switch into z (their stiffness, element, state at θ = 0) with their switches in
 * events, sorted by angle; the count of z's sliders into *S and of events into *count. */
static int schedule(fricreg_hb *hb, const char *fn, struct fr_hb_mono *w, size_t *S, size_t *count)
{
    size_t nc = hb->nc;
    *S = *count = 0;
    for (size_t e = 0; e < hb->me; e++) {
        const double *k, *phi;
        size_t ns = fr_hb_sliders(hb, e, &k, &phi);
        for (size_t s = 0; s < ns; s++) {
            struct fr_aft_slips sl = {.on = w->on, .off = w->off};
            int status = fr_aft_exact_slips(hb->aft, fn, k[s], phi[s], hb->qjac + e * nc, &sl);
            if (status != FRICREG_OK)
                return fr_fail(hb, status, "%s: stability: the AFT of element %zu failed: %s", fn,
                               e, fricreg_aft_errmsg(hb->aft));
            if (sl.kind == FR_AFT_STUCK)
                add_stuck_stiffness(hb, w, e, k[s]);
            if (sl.kind != FR_AFT_SLIPS)
                continue;
            size_t j = (*S)++;
            w->k[j] = k[s];
            w->element[j] = e;
            w->slipping[j] = 0;
            for (int i = 0; i < sl.count; i++) {
                w->slipping[j] |= sl.off[i] < sl.on[i]; /* across θ = 0 */
                w->events[(*count)++] = (struct switch_event){sl.on[i], j, 1};
                w->events[(*count)++] = (struct switch_event){sl.off[i], j, 0};
            }
        }
    }
    qsort(w->events, *count, sizeof *w->events, by_angle);
    return FRICREG_OK;
}

/* dt A of the piece with z's S sliders in their current state, column-major [P P]. */
static void piece_matrix(const fricreg_hb *hb, struct fr_hb_mono *w, size_t S, double dt)
{
    size_t n = hb->n, P = 2 * n + S;
    double *A = w->A;
    memset(A, 0, P * P * sizeof *A);
    for (size_t i = 0; i < n; i++)
        A[(n + i) * P + i] = dt;
    for (size_t l = 0; l < n; l++)
        for (size_t i = 0; i < n; i++) {
            A[l * P + n + i] = -dt * w->MiK[l * n + i];
            A[(n + l) * P + n + i] = -dt * w->MiC[l * n + i];
        }
    for (size_t j = 0; j < S; j++) {
        size_t e = w->element[j];
        const double *Je = hb->J + e * n, *mj = w->MiJ + e * n;
        if (w->slipping[j]) {
            for (size_t l = 0; l < n; l++)
                A[(n + l) * P + 2 * n + j] = dt * Je[l];
            continue;
        }
        for (size_t i = 0; i < n; i++) /* the stuck slider's spring k (J_e δx − δw) */
            A[(2 * n + j) * P + n + i] = dt * w->k[j] * mj[i];
        for (size_t l = 0; l < n; l++)
            if (Je[l] != 0.0)
                for (size_t i = 0; i < n; i++)
                    A[l * P + n + i] -= dt * w->k[j] * Je[l] * mj[i];
    }
}

/* Φ = e^{dt A} Φ over a piece of the period. */
static int advance(fricreg_hb *hb, const char *fn, struct fr_hb_mono *w, size_t S, double dt)
{
    size_t P = 2 * hb->n + S;
    piece_matrix(hb, w, S, dt);
    int info = fr_hb_expm(w->A, P, w->E, w->expm_work, w->piv);
    if (info != 0)
        return fr_fail(hb, FRICREG_ENONFINITE,
                       "%s: stability: the monodromy's piece of %g s has no finite exponential", fn,
                       dt);
    fr_hb_product(P, w->E, w->Phi, w->T);
    double *swap = w->Phi;
    w->Phi = w->T;
    w->T = swap;
    return FRICREG_OK;
}

/* The saltation of slider j's onset: its offset's row becomes J_e δx. */
static void onset(const fricreg_hb *hb, struct fr_hb_mono *w, size_t S, size_t j)
{
    size_t n = hb->n, P = 2 * n + S;
    const double *Je = hb->J + w->element[j] * n;
    for (size_t c = 0; c < P; c++) {
        double s = 0.0;
        for (size_t l = 0; l < n; l++)
            s += Je[l] * w->Phi[c * P + l];
        w->Phi[c * P + 2 * n + j] = s;
    }
}

/* (Φ) over the period T = 2π/Ω from the sorted switches. */
static int monodromy_matrix(fricreg_hb *hb, const char *fn, struct fr_hb_mono *w, size_t S,
                            size_t count, double omega)
{
    size_t P = 2 * hb->n + S;
    memset(w->Phi, 0, P * P * sizeof(double));
    for (size_t i = 0; i < P; i++)
        w->Phi[i * P + i] = 1.0;
    double theta = 0.0;
    for (size_t i = 0; i <= count; i++) {
        double next = i < count ? w->events[i].theta : FR_TWO_PI;
        int status = next > theta ? advance(hb, fn, w, S, (next - theta) / omega) : FRICREG_OK;
        if (status != FRICREG_OK)
            return status;
        theta = fmax(theta, next);
        if (i == count)
            break;
        size_t j = w->events[i].slider;
        w->slipping[j] = w->events[i].onset;
        if (w->events[i].onset)
            onset(hb, w, S, j);
    }
    return FRICREG_OK;
}

/* The 2n multipliers of Φ [P P] (destroyed) as exponents into out[2 + 4n], with the verdict and
 * the largest |μ| in out[0], out[1]: the S smallest |μ|, the sliders' zeros, dropped. */
static int multipliers(fricreg_hb *hb, const char *fn, struct fr_hb_mono *w, size_t S, double omega,
                       double *out)
{
    size_t P = 2 * hb->n + S;
    for (size_t i = 0; i < P * P; i++)
        if (!isfinite(w->Phi[i]))
            return fr_fail(hb, FRICREG_ENONFINITE,
                           "%s: stability: the monodromy overflows at Omega = %g", fn, omega);
    if (fr_hb_eigenvalues(w->Phi, P, w->wr, w->wi, w->eig_work, w->lwork) != 0)
        return fr_fail(hb, FRICREG_EINTEGRATOR,
                       "%s: stability: the QR iteration on the monodromy did not converge at "
                       "Omega = %g",
                       fn, omega);
    for (size_t d = 0; d < S; d++) { /* drop: mark the smallest left with a NaN modulus */
        size_t low = P;
        for (size_t i = 0; i < P; i++)
            if (!isnan(w->wr[i]) &&
                (low == P || hypot(w->wr[i], w->wi[i]) < hypot(w->wr[low], w->wi[low])))
                low = i;
        w->wr[low] = NAN;
    }
    double T = FR_TWO_PI / omega, top = 0.0, *exps = out + 2;
    size_t kept = 0;
    for (size_t i = 0; i < P; i++) {
        if (isnan(w->wr[i]))
            continue;
        double mod = hypot(w->wr[i], w->wi[i]);
        top = fmax(top, mod);
        exps[2 * kept] = log(fmax(mod, DBL_MIN)) / T;
        exps[2 * kept + 1] = atan2(w->wi[i], w->wr[i]) / T;
        kept++;
    }
    out[0] = log(top) <= FR_HB_STABLE_TOL ? 1.0 : 0.0;
    out[1] = top;
    return FRICREG_OK;
}

int fr_hb_monodromy(fricreg_hb *hb, const char *fn, double omega, double *out)
{
    int status = fr_hb_monodromy_reserve(hb, fn);
    if (status != FRICREG_OK)
        return status;
    struct fr_hb_mono *w = hb->mono;
    size_t S, count;
    dense_model(hb, w);
    if ((status = mass_solves(hb, fn, w)) != FRICREG_OK ||
        (status = schedule(hb, fn, w, &S, &count)) != FRICREG_OK ||
        (status = monodromy_matrix(hb, fn, w, S, count, omega)) != FRICREG_OK)
        return status;
    return multipliers(hb, fn, w, S, omega, out);
}
