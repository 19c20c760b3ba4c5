/* SPDX-License-Identifier: GPL-3.0-or-later */
/* nma_solve.c — one point of a nonlinear mode by the extended periodic motion concept (M.
 * Krack, "Nonlinear modal analysis of nonconservative systems: extension of the periodic motion
 * concept", Computers & Structures 154, 2015): the autonomous HB problem
 *
 *     M x'' + (C − ξ M) x' + K x + J^T f(J x) = 0,
 *
 * condensed on q = J x as the forced response is (fricreg_hb.h): D_h = K − (hω)² M +
 * i hω (C − ξ M), no load, so (R) reads R(q, ω, ξ) = q + G_h(ω, ξ) F_h(q) = 0, closed by the
 * amplitude and phase conditions on the first harmonic X_1 = −D_1^-1 J^T F_1 along the
 * mass-normalized linear mode φ:
 *
 *     s = φ^T M X_1 = −g^T F_1,   g = J D_1^-1 M φ,     Re s = a,  Im s = 0
 *
 * (the modal coordinate is a cos ωt). g is the condensation's load column with M φ as the load
 * (fricreg_hb_nma_enter), so its ω derivative comes with the factors'. The ξ derivatives, from
 * dD_h/dξ = −i hω M: dG_h/dξ = −Y_h^T (dD_h/dξ) Y_h (the same for g's column). Newton's method
 * on the nq + 2 unknowns (q, ω, ξ) with the exact Jacobian
 *
 *     [ I + G ∂F/∂q    dG/dω F    dG/dξ F ]
 *     [ −c Re g^T ∂F_1/∂q   −c Re dg/dω^T F_1   −c Re dg/dξ^T F_1 ]   (and the Im row)
 *
 * the amplitude rows weighted by c = (displacement scale)/a, and the backtracking line search of
 * newton.c (Armijo on the weighted |R|, halving down to 1/1024). */
#include <math.h>
#include <string.h>

#include "base/line_search.h"
#include "base/newton_loop.h"
#include "nma_internal.h"
#include "hb/dynamic.h"
#include "hb/lu.h"
#include "hb/residual.h"
#include "hb/monitor.h"

void fr_hb_nma_enter(fricreg_hb *hb, struct fr_hb_nma *nma)
{
    nma->saved_pc = hb->pc;
    nma->saved_ps = hb->ps;
    hb->pc = nma->w;
    hb->ps = nma->zero;
    hb->free_vibration = 1;
    hb->no_c = nma->modal;
    hb->factored_omega = NAN;
}

void fr_hb_nma_leave(fricreg_hb *hb, struct fr_hb_nma *nma)
{
    hb->pc = nma->saved_pc;
    hb->ps = nma->saved_ps;
    hb->free_vibration = 0;
    hb->no_c = 0;
    hb->xi = 0.0;
    hb->factored_omega = NAN; /* the factors were the mode's */
}

/* Z = (dD_h/dξ) Y_h = −i hω M Y_h (stiffness 0), or (dD_h/da1) Y_h = i hω K Y_h (stiffness 1:
 * Rayleigh's a1), dense or on the sparse pattern. */
static void damping_times_y(fricreg_hb *hb, int h, double omega, int stiffness)
{
    size_t n = hb->n, w = hb->m + 1;
    const double *Y = hb->Y + 2 * (size_t)h * n * w;
    const double *X = stiffness ? hb->K : hb->M, *vX = stiffness ? hb->vK : hb->vM;
    double s = stiffness ? h * omega : -h * omega;
    memset(hb->Z, 0, 2 * n * w * sizeof(double));
    for (size_t j = 0; j < n; j++) {
        int64_t p0 = hb->sparse ? hb->Dp[j] : 0, p1 = hb->sparse ? hb->Dp[j + 1] : (int64_t)n;
        for (int64_t p = p0; p < p1; p++) {
            size_t i = hb->sparse ? (size_t)hb->Di[p] : (size_t)p;
            double mij = hb->sparse ? vX[p] : X[i * n + j];
            if (mij == 0.0)
                continue;
            for (size_t c = 0; c < w; c++) { /* z += i s mij y */
                const double *y = Y + 2 * (j * w + c);
                double *z = hb->Z + 2 * (i * w + c);
                z[0] -= s * mij * y[1];
                z[1] += s * mij * y[0];
            }
        }
    }
}

void fr_hb_nma_damping_derivatives(fricreg_hb *hb, struct fr_hb_nma *nma, double omega,
                                   int stiffness)
{
    size_t m = hb->m;
    memset(nma->dGx, 0, 2 * m * m * sizeof(double)); /* h = 0: D_0 = K */
    memset(nma->dgx, 0, 2 * m * sizeof(double));
    for (int h = 1; h <= hb->H; h++) {
        damping_times_y(hb, h, omega, stiffness);
        fr_hb_project(hb, hb->Y + 2 * (size_t)h * hb->n * (m + 1), hb->Z, -1.0,
                      nma->dGx + 2 * (size_t)h * m * m, nma->dgx + 2 * (size_t)h * m);
    }
}

void fr_hb_nma_modal(const fricreg_hb *hb, const double *g, const double *f, double *s)
{
    size_t nc = hb->nc;
    s[0] = s[1] = 0.0;
    for (size_t r = 0; r < hb->m; r++) { /* F = fa − i fb */
        double gr = g[2 * r], gi = g[2 * r + 1], fa = f[r * nc + 1], fb = f[r * nc + 2];
        s[0] -= gr * fa + gi * fb;
        s[1] -= gi * fa - gr * fb;
    }
}

int fr_hb_nma_evaluate(fricreg_hb *hb, const char *fn, struct fr_hb_nma *nma, const double *y,
                       double *R)
{
    size_t nq = nma->nq;
    double omega = y[nq];
    if (!isfinite(omega) || !(omega > 0.0) || !isfinite(y[nq + 1]))
        return fr_fail(hb, FRICREG_EWORK, "%s: Newton left the frequencies (omega = %g, xi = %g)",
                       fn, omega, y[nq + 1]);
    double xi = y[nq + 1] - (nma->modal ? nma->xi_k : 0.0);
    if (xi != hb->xi) { /* D_h(ω, ξ): the factors at this ω are another ξ's */
        hb->xi = xi;
        hb->factored_omega = NAN;
    }
    int status = fr_hb_factor(hb, fn, omega, 1);
    if (status == FRICREG_OK)
        status = fr_hb_residual(hb, fn, y, R, 1);
    return status;
}

int fr_hb_nma_system(fricreg_hb *hb, const char *fn, struct fr_hb_nma *nma, const double *y,
                     double *R, int jac)
{
    size_t nq = nma->nq, nd = nma->nd, m = hb->m;
    int status = fr_hb_nma_evaluate(hb, fn, nma, y, R);
    if (status != FRICREG_OK)
        return status;
    double c = nma->scale / nma->amplitude, s[2];
    fr_hb_nma_modal(hb, hb->ql + 2 * m, hb->fq, s);
    R[nq] = c * (s[0] - nma->amplitude);
    R[nq + 1] = c * s[1];
    if (!jac)
        return FRICREG_OK;
    double *A = nma->A;
    fr_hb_nma_damping_derivatives(hb, nma, y[nq], 0);
    fr_hb_matrix(hb, hb->jq, A, nd);
    fr_hb_domega(hb, nma->col);
    for (size_t j = 0; j < nq; j++)
        A[j * nd + nq] = nma->col[j];
    fr_hb_apply(hb, nma->dGx, NULL, 0.0, hb->fq, nma->col);
    for (size_t j = 0; j < nq; j++)
        A[j * nd + nq + 1] = nma->col[j];
    /* the amplitude rows: ∂s/∂ω, ∂s/∂ξ from g's derivatives, ∂s/∂q from the forces' Jacobian */
    fr_hb_nma_modal(hb, hb->dql + 2 * m, hb->fq, s);
    A[nq * nd + nq] = c * s[0];
    A[(nq + 1) * nd + nq] = c * s[1];
    fr_hb_nma_modal(hb, nma->dgx + 2 * m, hb->fq, s);
    A[nq * nd + nq + 1] = c * s[0];
    A[(nq + 1) * nd + nq + 1] = c * s[1];
    size_t nc = hb->nc;
    for (size_t j = 0; j < nq; j++)
        A[nq * nd + j] = A[(nq + 1) * nd + j] = 0.0;
    for (size_t e = 0; e < hb->me; e++) {
        size_t rows = fr_hb_rows_of(hb, e), b = rows * nc, at = hb->erow[e] * nc;
        for (size_t sr = 0; sr < rows; sr++) {
            size_t r = hb->erow[e] + sr;
            const double *g = hb->ql + 2 * (m + r), *Ja = fr_hb_block_of(hb, e) + (sr * nc + 1) * b,
                         *Jb = Ja + b;
            for (size_t j = 0; j < b; j++) { /* ∂(−g F)/∂q_j, F = fa − i fb */
                A[nq * nd + at + j] -= c * (g[0] * Ja[j] + g[1] * Jb[j]);
                A[(nq + 1) * nd + at + j] -= c * (g[1] * Ja[j] - g[0] * Jb[j]);
            }
        }
    }
    return FRICREG_OK;
}

static double norm2(const double *v, size_t n)
{
    double s = 0.0;
    for (size_t j = 0; j < n; j++)
        s += v[j] * v[j];
    return sqrt(s);
}

/* Newton's step dy = −A^-1 R: FRICREG_ESINGULAR when a pivot of A's LU factor is below 1e-14 of
 * its largest entry. */
static int step(fricreg_hb *hb, const char *fn, struct fr_hb_nma *nma)
{
    size_t nd = nma->nd;
    double amax = 0.0;
    for (size_t k = 0; k < nd * nd; k++)
        amax = fmax(amax, fabs(nma->A[k]));
    fr_hb_lu_factor(nma->A, nd, nma->piv);
    for (size_t k = 0; k < nd; k++) {
        double p = fabs(nma->A[k * nd + k]);
        if (!(p > 1e-14 * amax) || !isfinite(p))
            return fr_fail(hb, FRICREG_ESINGULAR,
                           "%s: the nonlinear mode's Newton matrix is singular at amplitude %g "
                           "(pivot %zu: %g, largest entry %g)",
                           fn, nma->amplitude, k, p, amax);
    }
    for (size_t j = 0; j < nd; j++)
        nma->dy[j] = -nma->R[j];
    fr_hb_lu_solve_factored(nma->A, nd, nma->piv, nma->dy);
    return FRICREG_OK;
}

/* A trial y + alpha dy into yt, evaluated into Rt; accepted by Armijo on |R| (or at once when
 * converged), it becomes y. A trial the evaluation refuses (FRICREG_EWORK) is rejected, its
 * status kept in last for the report. */
struct nma_trial {
    fricreg_hb *hb;
    const char *fn;
    struct fr_hb_nma *nma;
    const struct fr_line_search *ls;
    int converged, last;
    double r0;
};

static int nma_trial(void *user, double alpha, int *accept)
{
    struct nma_trial *t = user;
    struct fr_hb_nma *nma = t->nma;
    size_t nd = nma->nd;
    for (size_t j = 0; j < nd; j++)
        nma->yt[j] = nma->y[j] + alpha * nma->dy[j];
    t->last = fr_hb_nma_system(t->hb, t->fn, nma, nma->yt, nma->Rt, 0);
    *accept = t->last == FRICREG_OK &&
              (t->converged || fr_armijo_decrease(t->ls, t->r0, norm2(nma->Rt, nd), alpha));
    if (*accept)
        memcpy(nma->y, nma->yt, nd * sizeof(double));
    return t->last == FRICREG_EWORK ? FRICREG_OK : t->last;
}

/* Backtracking along dy (Armijo's condition on |R|, as newton.c's); converged iterates take
 * the full step. *flat: no trial decreased |R| (each was evaluated). */
static int line_search(fricreg_hb *hb, const char *fn, struct fr_hb_nma *nma, int converged,
                       int *flat)
{
    struct fr_line_search ls = {FR_ARMIJO, FR_HB_HALVINGS, NULL};
    struct nma_trial t = {hb, fn, nma, &ls, converged, FRICREG_OK, norm2(nma->R, nma->nd)};
    int accepted, status = fr_line_search(&ls, 1.0, nma_trial, &t, &accepted);
    *flat = 0;
    if (status != FRICREG_OK || accepted)
        return status;
    *flat = t.last == FRICREG_OK;
    return t.last != FRICREG_OK ? t.last
                                : fr_fail(hb, FRICREG_EWORK,
                                          "%s: Newton's line search found no decrease of |R| = "
                                          "%g at amplitude %g",
                                          fn, t.r0, nma->amplitude);
}

/* The loop's view of a nonlinear mode's Newton at amplitude a (base/newton_loop.h): the
 * iterate y, converged once the largest |R_j| of its nd equations r <= bound, bound = tol
 * times the largest |y_j| of its nq harmonics. */
struct nma_loop {
    fricreg_hb *hb;
    const char *fn;
    struct fr_hb_nma *nma;
    double r, bound;
    int floor; /* converged at the rounding floor (nma_search) */
};

/* y evaluated (R and the Newton matrix) and measured. */
static int nma_evaluate(struct nma_loop *l)
{
    struct fr_hb_nma *nma = l->nma;
    int status = fr_hb_nma_system(l->hb, l->fn, nma, nma->y, nma->R, 1);
    if (status != FRICREG_OK)
        return status;
    double r = 0.0, qs = 0.0;
    for (size_t j = 0; j < nma->nd; j++)
        r = fmax(r, fabs(nma->R[j]));
    for (size_t j = 0; j < nma->nq; j++)
        qs = fmax(qs, fabs(nma->y[j]));
    l->r = r;
    l->bound = l->hb->tol * fmax(qs, 1e-300);
    return FRICREG_OK;
}

static int nma_converged(void *user)
{
    struct nma_loop *l = user;
    return l->r <= l->bound || l->floor;
}

/* Newton's own step dy within the tolerance of the unknowns: each q's change within tol
 * times the largest |q|, ω's and ξ's within tol times ω. */
static int step_within_tol(const struct nma_loop *l)
{
    const struct fr_hb_nma *nma = l->nma;
    size_t nq = nma->nq;
    double qs = 0.0, dq = 0.0, w = fabs(nma->y[nq]), tol = l->hb->tol;
    for (size_t j = 0; j < nq; j++) {
        qs = fmax(qs, fabs(nma->y[j]));
        dq = fmax(dq, fabs(nma->dy[j]));
    }
    return dq <= tol * qs && fabs(nma->dy[nq]) <= tol * w && fabs(nma->dy[nq + 1]) <= tol * w;
}

static int nma_progress(void *user, double rinf)
{
    struct nma_loop *l = user;
    (void)rinf; /* the monitor's measure is r / bound */
    return fr_hb_tick(l->hb, l->fn, l->nma->amplitude, l->r / l->bound);
}

static int nma_direction(void *user)
{
    struct nma_loop *l = user;
    return step(l->hb, l->fn, l->nma);
}

/* A search that accepts nothing is a failure here (line_search), unless Newton's own step is
 * within the tolerance of the unknowns: then |R| is at the rounding level of the model's scale
 * (its D_h's condition times the unit roundoff, which a tolerance on |R| relative to |q| does
 * not see), the iterate as good as the arithmetic gives, and converged there (the loop ends
 * on it). The accepted y evaluated. */
static int nma_search(void *user, double *phi, double *rinf, int *accepted)
{
    struct nma_loop *l = user;
    (void)phi;
    (void)rinf;
    int flat, status = line_search(l->hb, l->fn, l->nma, nma_converged(l), &flat);
    *accepted = status == FRICREG_OK;
    if (flat && step_within_tol(l)) {
        l->floor = 1;
        return FRICREG_OK;
    }
    return status == FRICREG_OK ? nma_evaluate(l) : status;
}

int fr_hb_nma_newton(fricreg_hb *hb, const char *fn, struct fr_hb_nma *nma, double a)
{
    size_t nq = nma->nq;
    nma->amplitude = a;
    nma->scale = 0.0;
    for (size_t j = 0; j < nq; j++)
        nma->scale = fmax(nma->scale, fabs(nma->y[j]));
    if (!(nma->scale > 0.0))
        nma->scale = a;
    struct nma_loop l = {hb, fn, nma, 0.0, 0.0, 0};
    int status = nma_evaluate(&l);
    if (status != FRICREG_OK)
        return status;
    struct fr_newton_loop nl = {1.0,          hb->max_iter, 1, &l, nma_direction, nma_search, NULL,
                                nma_progress, nma_converged};
    double phi = 0.0, rinf = 0.0; /* the loop's measures unused: nma_converged decides */
    int iters = 0;
    if ((status = fr_newton_loop_run(&nl, &phi, &rinf, &iters)) != FRICREG_OK)
        return status;
    if (iters == 0 || !nma_converged(&l))
        return fr_fail(hb, FRICREG_EWORK,
                       "%s: Newton did not converge in %d iterations at amplitude %g (|R| = %g, "
                       "tolerance %g)",
                       fn, iters, a, l.r, l.bound);
    hb->iterations = iters;
    return FRICREG_OK;
}
