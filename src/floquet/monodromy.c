/* SPDX-License-Identifier: GPL-3.0-or-later */
/* monodromy.c — the Floquet multipliers of a periodic HB solution from the exact monodromy of
 * its orbit, for elements that are piecewise linear (R. I. Leine, H. Nijmeijer, Dynamics and
 * Bifurcations of Non-Smooth Mechanical Systems, Springer 2004, Ch. 7: saltation matrices).
 *
 * With 1-D Jenkins and Iwan sliders, under a constant normal load or a linear normal law with
 * lift-off (N = max(0, N0 + kn g)), M x'' + C x' + K x + J^T f = p(t) is linear between the
 * switches (switches.c: the exact AFT's, on the solution's q(t) = J x(t)). A perturbation z =
 * (δx, δv, δw), δw the offsets of the sliders that switch, follows z' = A_k z on each piece k:
 *
 *     δx' = δv,   M δv' = −C δv − K δx − Σ J_t^T δf − Σ_closed kn J_n^T J_n δx,
 *     stick: δf = k (J_t δx − δw), δw' = 0;   slip in direction d: δf = d mu kn J_n δx,
 *     δw' = (J_t − d (mu kn/k) J_n) δv;   open: δf = 0,
 *
 * J_t, J_n an element's tangential and normal rows (kn = 0, no J_n, under a constant load). At
 * a slip onset the perturbed orbit switches when its own force reaches the bound, so the offset
 * then follows the slip's: the saltation δw ← (J_t − d (mu kn/k) J_n) δx; at a touchdown (the
 * offset set to u there, the instant moving with g) δw ← (J_t − (u'/g') J_n) δx; x and v stay
 * continuous, as f and N do, and at a stop or an opening nothing jumps. Hence
 *
 *     Φ = e^{A_K Δt_K} S_K ⋯ S_1 e^{A_1 Δt_1},   Δt_k the pieces of θ = Ω t over [0, 2π),    (Φ)
 *
 * each exponential by expm.c. A slider stuck over the whole period keeps a constant offset: its
 * multiplier is a neutral 1 (like HB's offset ambiguity), so it stays out of z, its stiffness
 * in K; one that slips throughout (or has no bound) exerts a fixed force and stays out too.
 * Each slider in z forgets its offset at its onsets, which gives Φ one zero multiplier per
 * such slider: as many of the smallest |μ| are dropped, and the 2n left are the multipliers,
 * λ = log μ / T (Im λ in (−Ω/2, Ω/2]) the exponents, in the layout of Hill's (hill.c). */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/fr_math.h"
#include "expm.h"
#include "joint/aft_slips.h"
#include "monodromy.h"
#include "orbit.h"
#include "piece_powers.h"
#include "reduction.h"
#include "switches.h"
#include "hb/lu.h"
#include "base/free_all.h"

/* The workspace, sized for a model of order n (the driver's dofs, or the condensed model's), m
 * rows of J, S sliders and H harmonics; column-major matrices of the order P = 2n + S at most;
 * J, the model's, row-major [m n]. */
struct fr_hb_mono {
    size_t n, m, S, P;
    int H;
    const double *J;
    double *Mlu, *MiK, *MiC, *MiJ; /* [n n] each, MiJ [n m]: M's LU, M^-1 K, M^-1 C, M^-1 J^T */
    double *A, *E, *Phi, *T, *expm_work; /* [P P] each, expm's [6 P P] */
    double *eig_work, *wr, *wi;          /* [lwork], [P], [P] */
    size_t lwork;
    /* linear_multipliers' last one-piece matrix (dt 1) [P P] and its eigenvalues [P], [P]:
     * the all-stuck points of a branch share them (lin_order 0: none kept) */
    double *lin_A, *lin_re, *lin_im;
    size_t lin_order;
    int *piv;     /* [P] */
    double sigma; /* the pieces' velocities in units of σ (piece_matrix) */
    struct fr_hb_schedule sc;
    struct fr_hb_pieces pieces; /* the pieces' matrices met before, with their powers */
    double *orbit_work;         /* orbit.h's workspace, then M^-1 p [2n]; NULL where none applies */
    int *orbit_piv;
};

void fr_hb_monodromy_free(fricreg_hb *hb)
{
    struct fr_hb_mono *w = hb->stability->mono;
    if (w == NULL)
        return;
    FR_FREE_ALL(w->Mlu, w->eig_work, w->piv, w->orbit_work, w->orbit_piv);
    fr_hb_schedule_free(&w->sc);
    fr_hb_pieces_free(&w->pieces);
    free(w);
    hb->stability->mono = NULL;
}

/* The workspace for a model of order n: FRICREG_OK or FRICREG_ENOMEM (recorded, with fn). */
static int reserve_order(fricreg_hb *hb, const char *fn, size_t n)
{
    size_t m = hb->m, S = hb->nsl, P = 2 * n + S;
    struct fr_hb_mono *w = hb->stability->mono;
    int orbit = hb->rpe == 2 && n <= FR_HB_ORBIT_MAX_N && S <= FR_HB_ORBIT_MAX_SLIDERS &&
                hb->me <= FR_HB_ORBIT_MAX_ELEMENTS; /* the instants may be refined (orbit.h) */
    if (w != NULL && w->n == n && w->m == m && w->S == S && w->H == hb->H &&
        (w->orbit_work != NULL) == orbit)
        return FRICREG_OK;
    fr_hb_monodromy_free(hb);
    w = calloc(1, sizeof *w);
    size_t lwork = fr_hb_eigenvalues_work(P), mats = 3 * n * n + n * m + 11 * P * P + 2 * P;
    int ok = w != NULL;
    if (ok) {
        *w = (struct fr_hb_mono){.n = n, .m = m, .S = S, .P = P, .H = hb->H, .lwork = lwork};
        w->Mlu = malloc(mats * sizeof(double));
        w->eig_work = malloc((lwork + 2 * P) * sizeof(double));
        w->piv = malloc(P * sizeof *w->piv);
        if (orbit) {
            w->orbit_work = malloc((fr_hb_orbit_work(n, S) + 2 * n) * sizeof(double));
            w->orbit_piv = malloc((2 * n + S + 3 + FR_HB_ORBIT_MAX_SWITCHES) * sizeof(int));
            ok = w->orbit_work && w->orbit_piv;
        }
        ok = ok && w->Mlu && w->eig_work && w->piv &&
             fr_hb_schedule_alloc(hb, &w->sc) == FRICREG_OK &&
             fr_hb_pieces_init(&w->pieces, P) == 0;
    }
    hb->stability->mono = w;
    if (!ok) {
        fr_hb_monodromy_free(hb);
        return fr_fail(hb, FRICREG_ENOMEM,
                       "%s: stability: no memory for the monodromy of order %zu", fn, P);
    }
    w->MiK = w->Mlu + n * n;
    w->MiC = w->MiK + n * n;
    w->MiJ = w->MiC + n * n;
    w->A = w->MiJ + n * m;
    w->E = w->A + P * P;
    w->Phi = w->E + P * P;
    w->T = w->Phi + P * P;
    w->expm_work = w->T + P * P;
    w->lin_A = w->expm_work + 6 * P * P;
    w->lin_re = w->lin_A + P * P;
    w->lin_im = w->lin_re + P;
    w->wr = w->eig_work + lwork;
    w->wi = w->wr + P;
    return FRICREG_OK;
}

int fr_hb_monodromy_reserve(fricreg_hb *hb, const char *fn)
{
    return reserve_order(hb, fn, hb->n);
}

int fr_hb_monodromy_applies(const fricreg_hb *hb)
{
    /* elements all of one kind (rpe), of as many sliders each (ns): not a mix */
    return hb->have_elements && (hb->rpe == 1 || hb->rpe == 2) && hb->ns > 0;
}

/* The model's M, C and K into Mlu, MiC, MiK: the driver's, dense (lm NULL), or the condensed
 * model's. */
static void model_matrices(const fricreg_hb *hb, struct fr_hb_mono *w,
                           const struct fr_hb_linear_model *lm)
{
    if (lm == NULL) {
        fr_hb_dense_model(hb, w->Mlu, w->MiC, w->MiK);
        w->J = hb->J;
        return;
    }
    size_t bytes = lm->n * lm->n * sizeof(double);
    memcpy(w->Mlu, lm->M, bytes);
    memcpy(w->MiK, lm->K, bytes);
    memcpy(w->MiC, lm->C, bytes);
    w->J = lm->J;
}

/* M^-1 K, M^-1 C in place and M^-1 J^T into MiJ, by M's LU (its pivots checked as Hill's): one
 * solve of the 2n + m columns, which lie in a row (K, C symmetric: their rows are columns). */
static int mass_solves(fricreg_hb *hb, const char *fn, struct fr_hb_mono *w)
{
    size_t n = w->n;
    int status = fr_hb_mass_lu(hb, fn, "the monodromy", n, w->Mlu, w->piv);
    if (status != FRICREG_OK)
        return status;
    memcpy(w->MiJ, w->J, hb->m * n * sizeof(double));
    fr_hb_lu_solve_many(w->Mlu, n, w->piv, 2 * n + hb->m, w->MiK);
    return FRICREG_OK;
}

/* out[n n] −= k (M^-1 J_a^T) J_b, rows a and b of J (the spring k J_a^T J_b in M^-1's image). */
static void sub_rank_one(const struct fr_hb_mono *w, size_t a, size_t b, double k, double *out,
                         size_t ld)
{
    size_t n = w->n;
    const double *Jb = w->J + b * n, *ma = w->MiJ + a * n;
    for (size_t l = 0; l < n; l++)
        if (Jb[l] != 0.0)
            for (size_t i = 0; i < n; i++)
                out[l * ld + i] -= k * Jb[l] * ma[i];
}

/* The row J_t − r J_n of element e (r = 0 or no normal row: J_t) into out[n]. */
static void slider_row(const fricreg_hb *hb, const struct fr_hb_mono *w, size_t e, double r,
                       double *out)
{
    size_t n = w->n, rpe = hb->rpe;
    const double *Jt = w->J + rpe * e * n;
    for (size_t l = 0; l < n; l++)
        out[l] = Jt[l] - (rpe == 2 && r != 0.0 ? r * Jt[n + l] : 0.0);
}

/* A of the piece with the schedule's sliders and contacts in their current states (its
 * exponential at the piece's duration dt is e^{dt A}), column-major [P P]; the x rows of the
 * velocity block in A's columns 0..n-1. */
static void piece_matrix(const fricreg_hb *hb, struct fr_hb_mono *w)
{
    const struct fr_hb_schedule *sc = &w->sc;
    size_t n = w->n, S = sc->S, P = 2 * n + S, rpe = hb->rpe;
    double *A = w->A, *row = w->wr; /* wr: free until the eigenvalues */
    memset(A, 0, P * P * sizeof *A);
    for (size_t i = 0; i < n; i++)
        A[(n + i) * P + i] = 1.0;
    for (size_t l = 0; l < n; l++)
        for (size_t i = 0; i < n; i++) {
            A[l * P + n + i] = -w->MiK[l * n + i];
            A[(n + l) * P + n + i] = -w->MiC[l * n + i];
        }
    for (size_t e = 0; e < hb->me; e++) /* the closed contacts' normal springs */
        if (rpe == 2 && sc->closed[e])
            sub_rank_one(w, 2 * e + 1, 2 * e + 1, sc->kn[e], A + n, P);
    for (size_t j = 0; j < S; j++) {
        size_t e = sc->element[j], t = rpe * e;
        double k = sc->k[j];
        if (!sc->closed[e] || sc->mode[j] == FR_AFT_OPEN)
            continue;
        if (sc->mode[j] == FR_AFT_STICK) { /* k (J_t δx − δw) */
            sub_rank_one(w, t, t, k, A + n, P);
            for (size_t i = 0; i < n; i++)
                A[(2 * n + j) * P + n + i] = k * w->MiJ[t * n + i];
            continue;
        }
        double d = sc->dir[j], c = sc->c[j]; /* slip: d mu kn J_n δx, the offset following */
        if (c != 0.0)
            sub_rank_one(w, t, t + 1, d * c, A + n, P);
        slider_row(hb, w, e, d * c / k, row);
        for (size_t l = 0; l < n; l++)
            A[(n + l) * P + 2 * n + j] = row[l];
    }
    /* in the state (δx, δv/σ, δw), σ near the fastest mode's frequency, A's blocks are of
     * one size (ω, not ω²): the same multipliers, and its norm, which sets the exponential's
     * squarings, is the fastest mode's ω dt instead of ω² dt */
    for (size_t c = 0; c < P; c++) {
        double fc = c >= n && c < 2 * n ? w->sigma : 1.0;
        for (size_t r = 0; r < P; r++)
            A[c * P + r] *= r >= n && r < 2 * n ? fc / w->sigma : fc;
    }
}

/* σ of piece_matrix: the square root of M^-1 K's norm (its largest column sum), or 1. */
static double velocity_scale(const struct fr_hb_mono *w)
{
    double norm = 0.0;
    for (size_t l = 0; l < w->n; l++) {
        double sum = 0.0;
        for (size_t i = 0; i < w->n; i++)
            sum += fabs(w->MiK[l * w->n + i]);
        norm = fmax(norm, sum);
    }
    return norm > 0.0 && isfinite(norm) ? sqrt(norm) : 1.0;
}

/* Φ = e^{dt A} Φ over a piece of the period: A's exponential from its kept powers where the
 * piece's matrix was met before (piece_powers.h), else afresh. */
static int advance(fricreg_hb *hb, const char *fn, struct fr_hb_mono *w, double dt)
{
    size_t P = 2 * w->n + w->sc.S;
    piece_matrix(hb, w);
    int info;
    const struct fr_hb_piece *kept = fr_hb_pieces_find(&w->pieces, w->A, P);
    if (kept != NULL)
        info = fr_hb_expm_at(kept->pow, kept->nu, P, dt, w->E, w->expm_work, w->piv);
    else {
        for (size_t i = 0; i < P * P; i++)
            w->A[i] *= dt;
        info = fr_hb_expm(w->A, P, w->E, w->expm_work, w->piv);
    }
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

/* A switch applied: the slider's or contact's new state, and a reset's saltation, the offset's
 * row of Φ becoming (J_t − r J_n) δx. */
static void apply(const fricreg_hb *hb, struct fr_hb_mono *w, const struct fr_hb_switch *s)
{
    struct fr_hb_schedule *sc = &w->sc;
    if (s->contact) {
        sc->closed[s->index] = s->mode;
        return;
    }
    size_t j = s->index, n = w->n, P = 2 * n + sc->S;
    sc->mode[j] = s->mode;
    sc->dir[j] = s->dir;
    if (s->reset == FR_AFT_KEEP)
        return;
    double r = s->reset == FR_AFT_TOUCHDOWN ? s->ratio : s->dir * sc->c[j] / sc->k[j], *row = w->wr;
    slider_row(hb, w, sc->element[j], r, row);
    for (size_t c = 0; c < P; c++) {
        double v = 0.0;
        for (size_t l = 0; l < n; l++)
            v += row[l] * w->Phi[c * P + l];
        w->Phi[c * P + 2 * n + j] = v;
    }
}

/* The angle of switch i of the schedule taken cyclically: i − count's, a period on. */
static double cyclic_theta(const struct fr_hb_schedule *sc, size_t i)
{
    return i < sc->count ? sc->sw[i].theta : sc->sw[i - sc->count].theta + FR_TWO_PI;
}

/* Φ over the switches first .. first + nsw − 1 (cyclically), each applied at its angle, and
 * the pieces between them, to the angle end. (Φ)'s product started at a switch instead of
 * θ = 0: Φ's first and last pieces, of one state, become one piece, and the product is Φ's
 * conjugate by the first piece (the same multipliers), one exponential less. */
static int product_from(fricreg_hb *hb, const char *fn, struct fr_hb_mono *w, double omega,
                        size_t first, size_t nsw, double end)
{
    const struct fr_hb_schedule *sc = &w->sc;
    size_t P = 2 * w->n + sc->S;
    memset(w->Phi, 0, P * P * sizeof(double));
    for (size_t i = 0; i < P; i++)
        w->Phi[i * P + i] = 1.0;
    double theta = cyclic_theta(sc, first);
    for (size_t i = first; i <= first + nsw; i++) {
        double next = i < first + nsw ? cyclic_theta(sc, i) : end;
        int status = next > theta ? advance(hb, fn, w, (next - theta) / omega) : FRICREG_OK;
        if (status != FRICREG_OK)
            return status;
        theta = fmax(theta, next);
        if (i < first + nsw)
            apply(hb, w, &sc->sw[i % sc->count]);
    }
    return FRICREG_OK;
}

/* (Φ) over the period T = 2π/Ω from the sorted switches, or over its first half where the
 * second repeats it (*power 2: Φ = Φ_h², the multipliers the squares of Φ_h's), from the first
 * switch on (there is one: a slider in the state switches, fr_hb_monodromy's one-piece orbits
 * aside). */
static int monodromy_matrix(fricreg_hb *hb, const char *fn, struct fr_hb_mono *w, double omega,
                            int *power)
{
    const struct fr_hb_schedule *sc = &w->sc;
    *power = fr_hb_schedule_half_wave(hb, sc) ? 2 : 1;
    size_t nsw = sc->count / (size_t)*power;
    return product_from(hb, fn, w, omega, 0, nsw, sc->sw[0].theta + FR_TWO_PI / *power);
}

/* The exponents into out[2 + 4n] from the kept multipliers' logarithms, log|μ| in re[P] and
 * arg μ in im[P] (a NaN re: dropped), and after them the condensed model's truncated modes'
 * (reduced); the verdict and the largest |μ| in out[0], out[1]. */
static void exponents(fricreg_hb *hb, size_t P, const double *re, const double *im, double omega,
                      int reduced, double *out)
{
    double T = FR_TWO_PI / omega, top = -INFINITY, *exps = out + 2; /* top: log max |μ| */
    size_t kept = 0;
    for (size_t i = 0; i < P; i++) {
        if (isnan(re[i]))
            continue;
        top = fmax(top, re[i]);
        exps[2 * kept] = re[i] / T;
        exps[2 * kept + 1] = im[i] / T;
        kept++;
    }
    size_t left_out = reduced ? fr_hb_reduction_truncated(hb, omega, exps + 2 * kept) : 0;
    for (size_t i = kept; i < kept + left_out; i++)
        top = fmax(top, exps[2 * i] * T);
    out[0] = top <= FR_HB_STABLE_TOL ? 1.0 : 0.0;
    out[1] = exp(top);
}

/* The 2n multipliers of Φ = Φ_h^power, Φ_h in w->Phi [P P] (destroyed), as exponents
 * (exponents above): the S smallest |μ|, the sliders' zeros, dropped. */
static int multipliers(fricreg_hb *hb, const char *fn, struct fr_hb_mono *w, double omega,
                       int power, int reduced, double *out)
{
    size_t S = w->sc.S, P = 2 * w->n + S;
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
    for (size_t i = 0; i < P; i++) { /* μ = ν^power into (log|μ|, arg μ), in place */
        if (isnan(w->wr[i]))
            continue;
        double mod = hypot(w->wr[i], w->wi[i]), arg = atan2(w->wi[i], w->wr[i]);
        w->wr[i] = power * log(fmax(mod, DBL_MIN));
        w->wi[i] = power == 1 ? arg : atan2(sin(power * arg), cos(power * arg));
    }
    exponents(hb, P, w->wr, w->wi, omega, reduced, out);
    return FRICREG_OK;
}

/* An orbit without switches: Φ = e^{A T}, A the one piece's, whose multipliers are e^{λ T} for
 * A's eigenvalues λ: the exponents from A's eigenvalues directly, without the exponential (its
 * products and log2 ‖A T‖ squarings) and its rounding of the damped modes. A is the same at
 * every point of a branch where the same sliders stick throughout (the same model, springs and
 * σ): its eigenvalues are kept, and a point whose A equals the last one's reuses them. */
static int linear_multipliers(fricreg_hb *hb, const char *fn, struct fr_hb_mono *w, double omega,
                              int reduced, double *out)
{
    size_t P = 2 * w->n; /* no slider switches: none in the state */
    piece_matrix(hb, w);
    if (w->lin_order != P || memcmp(w->A, w->lin_A, P * P * sizeof *w->A) != 0) {
        for (size_t i = 0; i < P * P; i++)
            if (!isfinite(w->A[i]))
                return fr_fail(hb, FRICREG_ENONFINITE,
                               "%s: stability: the model's matrix overflows at Omega = %g", fn,
                               omega);
        w->lin_order = 0;
        memcpy(w->lin_A, w->A, P * P * sizeof *w->A);
        if (fr_hb_eigenvalues(w->A, P, w->lin_re, w->lin_im, w->eig_work, w->lwork) != 0)
            return fr_fail(hb, FRICREG_EINTEGRATOR,
                           "%s: stability: the QR iteration on the model's matrix did not "
                           "converge at Omega = %g",
                           fn, omega);
        w->lin_order = P;
    }
    double T = FR_TWO_PI / omega;
    for (size_t i = 0; i < P; i++) { /* λ T = (log|μ|, arg μ + 2π k): arg μ into (−π, π] */
        w->wr[i] = w->lin_re[i] * T;
        w->wi[i] = atan2(sin(w->lin_im[i] * T), cos(w->lin_im[i] * T));
    }
    exponents(hb, P, w->wr, w->wi, omega, reduced, out);
    return FRICREG_OK;
}

/* Whether the orbit's model between switches is the one orbit.h knows: elements with lift-off
 * whose sliders are all in the state (Jenkins elements that switch) or carry no force (mu 0),
 * none stuck throughout (its offset, a constant of the HB's, is no state). */
static int refinable(const fricreg_hb *hb, const struct fr_hb_mono *w)
{
    const struct fr_hb_schedule *sc = &w->sc;
    if (hb->rpe != 2 || sc->nstuck != 0 || sc->count == 0)
        return 0;
    for (size_t e = 0; e < hb->me; e++) {
        int in_state = 0;
        for (size_t j = 0; j < sc->S; j++)
            in_state |= sc->element[j] == e;
        if (hb->nl[hb->me + e] != 0.0 && !(hb->ns == 1 && in_state))
            return 0;
    }
    return 1;
}

/* The switches moved onto the exact orbit nearest the HB's (orbit.h), on the whole model: M^-1 p from M's LU (mass_solves' pivots, before the
 * exponentials reuse them). 1 where the instants were moved, else 0 (the HB's kept). */
static int exact_switches(fricreg_hb *hb, struct fr_hb_mono *w, double omega)
{
    size_t n = w->n, me = hb->me;
    if (w->orbit_work == NULL || w->sc.count > FR_HB_ORBIT_MAX_SWITCHES)
        return 0;
    double *Mip = w->orbit_work + fr_hb_orbit_work(n, w->S), level = fr_hb_load(hb);
    for (size_t i = 0; i < n; i++)
        Mip[i] = level * hb->pc[i], Mip[n + i] = level * hb->ps[i];
    fr_hb_lu_solve_many(w->Mlu, n, w->piv, 2, Mip);
    struct fr_hb_orbit_model om = {.n = n,
                                   .m = hb->m,
                                   .me = me,
                                   .S = w->sc.S,
                                   .element = w->sc.element,
                                   .k = w->sc.k,
                                   .c = w->sc.c,
                                   .MiK = w->MiK,
                                   .MiC = w->MiC,
                                   .MiJ = w->MiJ,
                                   .J = w->J,
                                   .n0 = hb->nl + 2 * me,
                                   .kn = hb->nl + 3 * me,
                                   .Mip = Mip,
                                   .omega = omega};
    return fr_hb_orbit_refine(&om, &w->sc, w->orbit_work, w->orbit_piv);
}

int fr_hb_monodromy(fricreg_hb *hb, const char *fn, double omega, int condensed, double *out)
{
    struct fr_hb_linear_model lm;
    int status = condensed ? fr_hb_reduction_update(hb, fn, omega, &lm) : FRICREG_OK;
    if (status == FRICREG_OK)
        status = reserve_order(hb, fn, condensed ? lm.n : hb->n);
    if (status != FRICREG_OK)
        return status;
    struct fr_hb_mono *w = hb->stability->mono;
    model_matrices(hb, w, condensed ? &lm : NULL);
    if ((status = mass_solves(hb, fn, w)) != FRICREG_OK ||
        (status = fr_hb_schedule(hb, fn, &w->sc)) != FRICREG_OK)
        return status;
    /* the HB orbit's instants err by its truncation over the velocity at the surface: taken
     * from the exact orbit where the model is one orbit.c knows (it says why) */
    if (!condensed && refinable(hb, w))
        exact_switches(hb, w, omega);
    for (size_t i = 0; i < w->sc.nstuck; i++) { /* the sliders stuck throughout: springs */
        size_t t = hb->rpe * w->sc.stuck_element[i];
        sub_rank_one(w, t, t, -w->sc.stuck_k[i], w->MiK, w->n);
    }
    w->sigma = velocity_scale(w);
    if (w->sc.count == 0 && w->sc.S == 0) /* nothing switches: one piece */
        return linear_multipliers(hb, fn, w, omega, condensed, out);
    int power = 1;
    if ((status = monodromy_matrix(hb, fn, w, omega, &power)) != FRICREG_OK)
        return status;
    return multipliers(hb, fn, w, omega, power, condensed, out);
}
