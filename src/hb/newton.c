/* SPDX-License-Identifier: GPL-3.0-or-later */
/* newton.c — the HB equations (R) at one frequency: the starting guesses (every element stuck,
 * or slipping freely) and Newton's method with a backtracking line search on |R| (Armijo's
 * condition with c = 1e-4, halving down to 1/1024; Nocedal & Wright, Numerical Optimization,
 * 2nd ed., Alg. 3.1 on the merit function of their Sec. 11.2; base/line_search.h). */
#include <math.h>
#include <string.h>

#include "base/line_search.h"
#include "base/newton_loop.h"
#include "hb_internal.h"
#include "joint/element_kind.h"
#include "residual.h"
#include "newton.h"
#include "newton_matrix.h"
#include "monitor.h"

static double norm2(const double *v, size_t n)
{
    double s = 0.0;
    for (size_t j = 0; j < n; j++)
        s += v[j] * v[j];
    return sqrt(s);
}

static double norm_inf(const double *v, size_t n)
{
    double s = 0.0;
    for (size_t j = 0; j < n; j++)
        s = fmax(s, fabs(v[j]));
    return s;
}

/* A marched element's block of the stuck guess: its law's elastic stiffness on each
 * component's harmonics, and on its normal component's mean too (a closed normal spring),
 * as the other kinds' below. */
static void stuck_march(const fricreg_hb *hb, size_t e, double *J)
{
    const fricreg_element_type *type = hb->etype[e];
    size_t nc = hb->nc, rows = fr_hb_rows_of(hb, e), b = rows * nc;
    double k[3];
    type->kind->elastic(type, hb->ep + hb->epo[e], k);
    for (size_t r = 0; r < rows; r++)
        for (size_t c = type->kind->normal && r == rows - 1 ? 0 : 1; c < nc; c++)
            J[(r * nc + c) * b + r * nc + c] = k[r];
}

int fr_hb_guess(fricreg_hb *hb, const char *fn, int stuck)
{
    size_t nq = hb->nq, nc = hb->nc;
    memset(hb->qt, 0, nq * sizeof(double));
    int status = fr_hb_residual(hb, fn, hb->qt, hb->R, 0); /* R = G F(0) − ql */
    if (status != FRICREG_OK)
        return status;
    for (size_t j = 0; j < nq; j++)
        hb->qw[j] = -hb->R[j];
    if (!stuck)
        return FRICREG_OK;
    /* the centred stick: f_h = kt q_h for h >= 1, f_0 = 0 (fricreg_aft.h); with lift-off
     * closed too, N = N0 + kn g on every harmonic */
    size_t me = hb->me;
    memset(hb->jq, 0, hb->ejq[hb->count] * nc * nc * sizeof(double));
    for (size_t e = 0; e < me; e++) {
        size_t rows = fr_hb_rows_of(hb, e), b = rows * nc;
        double *J = fr_hb_block_of(hb, e);
        if (hb->kind[e] == FR_HB_MARCH) {
            stuck_march(hb, e, J);
            continue;
        }
        if (hb->kind[e] == FR_HB_SLIDERS) {
            const double *k, *phi;
            size_t ns = fr_hb_sliders(hb, e, &k, &phi);
            double kt = 0.0;
            for (size_t s = 0; s < ns; s++)
                kt += k[s];
            for (size_t c = 1; c < nc; c++)
                J[c * nc + c] = kt;
            continue;
        }
        size_t normal_row = rows - 1; /* with lift-off, the last row of each element */
        for (size_t r = 0; r < rows; r++)
            for (size_t c = r == normal_row ? 0 : 1; c < nc; c++) {
                size_t i = r * nc + c;
                J[i * b + i] = r == normal_row ? hb->nl[3 * me + e] : hb->nl[e];
            }
    }
    fr_hb_newton_matrix(hb, nq, NULL, NULL);
    return fr_hb_newton_solve(hb, fn, hb->qw, hb->qw);
}

/* A trial qw + alpha dy into qt and its residual rw; accepted by Armijo on |R| (or at once
 * when converged), they become qw and R (with fq, jq at it). */
struct hb_trial {
    fricreg_hb *hb;
    const char *fn;
    const struct fr_line_search *ls;
    int converged;
    double r0;
};

static int hb_trial(void *user, double alpha, int *accept)
{
    struct hb_trial *t = user;
    fricreg_hb *hb = t->hb;
    size_t nq = hb->nq;
    for (size_t j = 0; j < nq; j++)
        hb->qt[j] = hb->qw[j] + alpha * hb->dy[j];
    int status = fr_hb_residual(hb, t->fn, hb->qt, hb->rw, 1);
    if (status != FRICREG_OK)
        return status;
    *accept = t->converged || fr_armijo_decrease(t->ls, t->r0, norm2(hb->rw, nq), alpha);
    if (*accept) {
        memcpy(hb->qw, hb->qt, nq * sizeof(double));
        memcpy(hb->R, hb->rw, nq * sizeof(double));
    }
    return FRICREG_OK;
}

/* Newton's direction dy = −A⁻¹ R at qw from the Jacobians in jq (qw's, or a trial's). */
static int direction(fricreg_hb *hb, const char *fn)
{
    fr_hb_newton_matrix(hb, hb->nq, NULL, NULL);
    for (size_t j = 0; j < hb->nq; j++)
        hb->dy[j] = -hb->R[j];
    return fr_hb_newton_solve(hb, fn, hb->dy, hb->dy);
}

/* Backtracking from qw along dy: the first of alpha = 1, 1/2, ..., 1/1024 whose residual
 * meets Armijo's condition on |R| becomes qw (with R, fq, jq at it). Converged iterates
 * (|R| within the tolerance already) take the full step: rounding decides there.
 *
 * A kink: where an element's stick/slip pattern changes, R is piecewise smooth, and near the
 * crossing Newton's direction of the side qw lies on points to that side's linear model's
 * root beyond the crossing, where R is another function; each step stops short of the
 * crossing, closer every time, until no trial decreases |R| (the seeded solve of NLvib's chain
 * at its onset of stick, tests/hb/test_hb_kinks.c: 5 shrinking steps, then none). Then the
 * shortest trial, past the crossing by at most 1/1024 of the step, left its Jacobian in jq:
 * the other side's, a limit of Jacobians near qw (an element of the generalized Jacobian of
 * piecewise-smooth Newton; Qi & Sun, Math. Prog. 58, 1993). Newton's direction from qw with
 * it, searched once more, reaches the root on that side (there: the full step, then two
 * more). Only a search that has failed takes it, so the converging iterations are as before. */
static int line_search(fricreg_hb *hb, const char *fn, int converged)
{
    struct fr_line_search ls = {FR_ARMIJO, FR_HB_HALVINGS, NULL};
    struct hb_trial t = {hb, fn, &ls, converged, norm2(hb->R, hb->nq)};
    int accepted, status = fr_line_search(&ls, 1.0, hb_trial, &t, &accepted);
    if (status != FRICREG_OK || accepted)
        return status;
    if (direction(hb, fn) == FRICREG_OK) { /* jq: the shortest trial's */
        status = fr_line_search(&ls, 1.0, hb_trial, &t, &accepted);
        if (status != FRICREG_OK || accepted)
            return status;
    }
    return fr_fail(hb, FRICREG_EWORK,
                   "%s: Newton's line search found no decrease of |R| = %g, nor along the "
                   "direction of the Jacobian past its shortest trial (a kink)",
                   fn, t.r0);
}

/* The loop's view of Newton at one frequency (base/newton_loop.h): the iterate qw, converged
 * once |R|_inf <= bound, bound = tol times the iterate's scale. */
struct hb_loop {
    fricreg_hb *hb;
    const char *fn;
    double r, bound; /* the iterate's |R|_inf and bound */
};

static void measure(struct hb_loop *l)
{
    l->r = norm_inf(l->hb->R, l->hb->nq);
    l->bound = l->hb->tol * fr_hb_scale(l->hb, l->hb->qw);
}

static int hb_converged(void *user)
{
    struct hb_loop *l = user;
    return l->r <= l->bound;
}

static int hb_progress(void *user, double rinf)
{
    struct hb_loop *l = user;
    (void)rinf; /* the monitor's measure is |R|_inf / bound */
    return fr_hb_tick(l->hb, l->fn, fr_hb_parameter(l->hb), l->r / l->bound);
}

static int hb_direction(void *user)
{
    struct hb_loop *l = user;
    return direction(l->hb, l->fn);
}

/* A search that accepts nothing is a failure here (FRICREG_EWORK, line_search). */
static int hb_search(void *user, double *phi, double *rinf, int *accepted)
{
    struct hb_loop *l = user;
    (void)phi;
    (void)rinf;
    int status = line_search(l->hb, l->fn, hb_converged(l));
    *accepted = status == FRICREG_OK;
    if (status == FRICREG_OK)
        measure(l);
    return status;
}

int fr_hb_newton(fricreg_hb *hb, const char *fn)
{
    int status = fr_hb_residual(hb, fn, hb->qw, hb->R, 1);
    if (status != FRICREG_OK)
        return status;
    struct hb_loop l = {hb, fn, 0.0, 0.0};
    struct fr_newton_loop nl = {1.0,       hb->max_iter, 1,           &l,          hb_direction,
                                hb_search, NULL,         hb_progress, hb_converged};
    double phi = 0.0, rinf = 0.0; /* the loop's measures unused: hb_converged decides */
    int iters = 0;
    measure(&l);
    if ((status = fr_newton_loop_run(&nl, &phi, &rinf, &iters)) != FRICREG_OK)
        return status;
    if (iters == 0 || !hb_converged(&l))
        return fr_fail(hb, FRICREG_EWORK,
                       "%s: Newton did not converge in %d iterations (|R| = %g, tolerance %g)", fn,
                       iters, l.r, l.bound);
    hb->iterations = iters;
    return FRICREG_OK;
}
