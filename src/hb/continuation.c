/* SPDX-License-Identifier: GPL-3.0-or-later */
/* continuation.c — the frequency response by pseudo-arclength continuation (H. B. Keller,
 * "Numerical solution of bifurcation and nonlinear eigenvalue problems", 1977; Krack & Gross
 * 2019, Ch. 5) on the scaled unknowns y = (q/qs, Ω/ws), qs the starting solution's displacement
 * scale raised to the largest |q| the branch reaches, ws = |Ω1 − Ω0|: the tangent t from
 * [R_q R_Ω; d^T] t = [0; 1], normalized, d the previous direction; the predictor y + ds t; the
 * corrector Newton's method on (R) bordered by t^T (y − y_pred) = 0, with a line search.
 *
 * The step control after E. L. Allgower and K. Georg, "Numerical Continuation Methods: An
 * Introduction", Springer 1990, Ch. 6 (steplength adaptation by asymptotic estimates): from
 * the corrector's first step δ, its contraction κ = |Δy_2|/|Δy_1|, the angle α between
 * successive tangents, and the corrector's iterations (as NLvib's solve_and_continue, Krack &
 * Gross Ch. 4–5), the next step is ds / f, f = max(κ/κ0, (δ/ds)/δ0, α/α0, its/its0) within
 * [1/2, 2]. A step is rejected (ds halved) when the corrector fails, ends farther than 4 ds
 * from the last point (it jumped along the branch, e.g. across a sharp peak), turns the chord
 * by more than twice the tangent's angle (it joined another part of the branch: the flanks of
 * a sharp peak meet at q = 0 a tiny Ω apart), turns the tangent by more than 20°, or
 * contracts by more than 1/2 in its first steps. The exact AFT's Jacobian is not smooth where
 * an element's stick/slip or contact pattern changes, and there the branch has a kink: the
 * angle and the contraction do not fall with ds. A converged corrector whose tangent turned by
 * less than 90° is accepted there, once halving ds no longer lowered them by a quarter, or
 * when halving would go below ds_min (a converged residual is a solution). Below ds_min the
 * step is predicted once more along the secant of the last two points before the
 * continuation stops. A branch that runs back along itself (a point near an earlier stretch, heading the same way)
 * stops it. The points' Ω, RMS and unknowns are stored; fricreg_hb_peak locates each dof's
 * largest RMS between them. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/line_search.h"
#include "hb_internal.h"

/* The step control's nominal values (Allgower & Georg give the form; these were chosen on
 * tests/test_hb_continuation.c's chains and lift-off pair): the corrector's contraction, its
 * first step relative to ds, the angle between successive tangents (rad), the iterations; the
 * bounds on the angle (20°; a kink's 90°), on the contraction (1/2: Newton's convergence is
 * slow beyond) and on the distance from the last point (4 ds: the hyperplane of a kink of up
 * to 75° meets the branch within ds / cos 75° < 4 ds); the chord's slack over twice the
 * tangents' angle. */
#define KAPPA0 0.25
#define DELTA0 0.3
#define ALPHA0 0.1745329251994330 /* 10° */
#define ITS0 4.0
#define ALPHA_MAX 0.3490658503988659 /* 20° */
#define KAPPA_MAX 0.5
#define KINK_MAX 1.5707963267948966 /* 90°: a larger turn goes back along the branch */
#define JUMP 4.0
#define CHORD_SLACK 1e-3 /* rad: above the chord's rounding, about tol/ds_min = 1e-4 */

struct branch {
    int level;       /* the parameter p is the excitation level λ at the fixed Ω omega, else Ω */
    double omega;    /* a level branch's Ω */
    const char *par; /* the parameter's name in messages */
    int keep;        /* the points are stored (a public continuation), else only counted */
    size_t count;    /* the points reached */
    double qs, ws;   /* the scales: y = (q/qs, p/ws) */
    double *yc;      /* [nq + 1] the last point, scaled */
    double *yp;      /* [nq + 1] the predictor */
    double *yo;      /* [nq + 1] the point before, scaled (have_prev) */
    int have_prev;
    double delta, kappa; /* the last corrector's first step and contraction */
    char why[256];       /* the last failed step's message */
};

/* Room for `want` points (at most max_points), kept on failure: FRICREG_ENOMEM. The unknowns'
 * room follows nq, which the element setters change (1 or 2 rows per element). */
static int reserve(fricreg_hb *hb, size_t want)
{
    size_t stride = hb->nq + 1, xw = FR_HB_XW(hb);
    if (want > hb->max_points)
        want = hb->max_points;
    if (want <= hb->cap && hb->qpts_stride == stride && hb->xpts_stride == xw)
        return FRICREG_OK;
    if (want < hb->cap)
        want = hb->cap;
    double *p = realloc(hb->pts, want * (1 + hb->n) * sizeof(double));
    if (p != NULL)
        hb->pts = p;
    double *q = p == NULL ? NULL : realloc(hb->qpts, want * stride * sizeof(double));
    if (q != NULL)
        hb->qpts = q;
    double *x = q == NULL ? NULL : realloc(hb->xpts, want * xw * sizeof(double));
    if (x != NULL)
        hb->xpts = x;
    double *f = x == NULL ? NULL : realloc(hb->bifs, want * (4 + hb->n) * sizeof(double));
    if (f == NULL)
        return fr_fail(hb, FRICREG_ENOMEM, "continue: no memory for %zu points", want);
    hb->bifs = f;
    hb->qpts_stride = stride;
    hb->xpts_stride = xw;
    hb->cap = want;
    return FRICREG_OK;
}

/* The sign of the determinant of the LU factor in A (order ld, pivots piv2). */
static double det_sign(const fricreg_hb *hb, size_t ld)
{
    double sign = 1.0;
    for (size_t k = 0; k < ld; k++)
        sign *= (hb->A[k * ld + k] < 0.0 ? -1.0 : 1.0) * (hb->piv2[k] != k ? -1.0 : 1.0);
    return sign;
}

/* The Ω of the branch's point of parameter p. */
static double omega_of(const struct branch *b, double p)
{
    return b->level ? b->omega : p;
}

/* The point at qt (unscaled q, parameter p; the factors, forces fq and Jacobians jq at it, the
 * level in force) stored, with the tangent's parameter component tw and the bordered matrix's
 * determinant sign det; its stability by Hill's method when on (already in xsol when
 * hill_done: fr_hb_solve_at's). Only counted when the branch keeps no points. */
static int store_point(fricreg_hb *hb, const char *fn, struct branch *b, double p, double tw,
                       double det, int hill_done)
{
    size_t w = 1 + hb->n, nq = hb->nq, xw = FR_HB_XW(hb);
    double omega = omega_of(b, p);
    b->count++;
    if (!b->keep)
        return FRICREG_OK;
    int status = hb->npts < hb->cap ? FRICREG_OK : reserve(hb, 2 * hb->cap);
    if (status != FRICREG_OK)
        return status;
    if (hb->stability && !hill_done && (status = fr_hb_hill(hb, fn, omega, hb->xsol + 2)))
        return status;
    double *x = hb->xpts + hb->npts * xw;
    x[0] = tw;
    x[1] = det;
    if (hb->stability)
        memcpy(x + 2, hb->xsol + 2, (xw - 2) * sizeof(double));
    hb->pts[hb->npts * w] = omega;
    fr_hb_rms(hb, hb->pts + hb->npts * w + 1);
    memcpy(hb->qpts + hb->npts * (nq + 1), hb->qt, nq * sizeof(double));
    hb->qpts[hb->npts * (nq + 1) + nq] = p;
    hb->npts++;
    memcpy(hb->qsol, hb->qt, nq * sizeof(double));
    hb->omega_sol = omega;
    hb->level_sol = hb->level;
    hb->have_solution = 1;
    return FRICREG_OK;
}

static double dot(const double *a, const double *b, size_t n)
{
    double s = 0.0;
    for (size_t j = 0; j < n; j++)
        s += a[j] * b[j];
    return s;
}

static double dist(const double *a, const double *b, size_t n)
{
    double s = 0.0;
    for (size_t j = 0; j < n; j++)
        s += (a[j] - b[j]) * (a[j] - b[j]);
    return sqrt(s);
}

/* Residual (scaled) at y into R[nq + 1] (the arclength equation last, when yp is given) and
 * the bordered matrix into A: [R_q, R_p ws/qs; row^T], p = Ω (R_Ω from the factors'
 * derivatives) or λ (R_λ = −ql: the load enters (R) linearly). qt holds the unscaled q, and
 * a level branch's λ is the level in force. */
static int bordered(fricreg_hb *hb, const char *fn, const struct branch *b, const double *y,
                    const double *row)
{
    size_t nq = hb->nq, ld = nq + 1;
    double omega = omega_of(b, y[nq] * b->ws);
    if (!(omega > 0.0))
        return fr_fail(hb, FRICREG_EINVAL, "%s: the branch reached Omega = %g <= 0", fn, omega);
    if (b->level)
        hb->level = y[nq] * b->ws;
    int status = fr_hb_factor(hb, fn, omega, !b->level);
    for (size_t j = 0; j < nq; j++)
        hb->qt[j] = y[j] * b->qs;
    if (status == FRICREG_OK)
        status = fr_hb_residual(hb, fn, hb->qt, hb->R, 1);
    if (status != FRICREG_OK)
        return status;
    if (b->level)
        fr_hb_dlevel(hb, hb->rw);
    else
        fr_hb_domega(hb, hb->rw);
    fr_hb_matrix(hb, hb->jq, hb->A, ld);
    for (size_t j = 0; j < nq; j++) {
        hb->R[j] /= b->qs;
        hb->A[j * ld + nq] = hb->rw[j] * b->ws / b->qs;
    }
    memcpy(hb->A + nq * ld, row, ld * sizeof(double));
    return FRICREG_OK;
}

/* The unit tangent into t from the bordered matrix in A (its last row the border d, not yet
 * factored): [R_q R_Ω; d^T] t = [0; 1], so d^T t > 0 orients it along d. */
static int tangent_from_matrix(fricreg_hb *hb, const char *fn, double *t)
{
    size_t ld = hb->nq + 1;
    memset(t, 0, ld * sizeof(double));
    t[ld - 1] = 1.0;
    int status = fr_hb_lu_solve(hb, fn, ld, t, t);
    if (status != FRICREG_OK)
        return status;
    double s = sqrt(dot(t, t, ld));
    for (size_t j = 0; j < ld; j++)
        t[j] /= s;
    return FRICREG_OK;
}

/* The corrector's iterate qw evaluated: R (the border's equation g last) and the bordered
 * matrix (bordered), the largest |R_j| r against its bound, |R| in norm; converged when both
 * equations are within their tolerances. */
struct corrector_iterate {
    fricreg_hb *hb;
    const char *fn;
    const struct branch *b;
    const double *anchor, *border, *base; /* base: the iterate the direction dy starts from */
    const struct fr_line_search *ls;
    double g, r, bound, norm, prev; /* prev: |R| at base */
    int converged;
};

static int corrector_evaluate(struct corrector_iterate *c)
{
    fricreg_hb *hb = c->hb;
    size_t nq = hb->nq, ld = nq + 1;
    int status = bordered(hb, c->fn, c->b, hb->qw, c->border);
    if (status != FRICREG_OK)
        return status;
    c->g = 0.0;
    c->r = 0.0;
    for (size_t j = 0; j < ld; j++)
        c->g += c->border[j] * (hb->qw[j] - c->anchor[j]);
    hb->R[nq] = c->g;
    for (size_t j = 0; j < nq; j++)
        c->r = fmax(c->r, fabs(hb->R[j]));
    c->bound = hb->tol * fr_hb_scale(hb, hb->qt) / c->b->qs;
    c->norm = sqrt(dot(hb->R, hb->R, ld));
    c->converged = c->r <= c->bound && fabs(c->g) <= hb->tol;
    return FRICREG_OK;
}

/* A trial base + lambda dy, evaluated into qw; accepted when converged or by Armijo on |R|. */
static int corrector_trial(void *user, double lambda, int *accept)
{
    struct corrector_iterate *c = user;
    fricreg_hb *hb = c->hb;
    for (size_t j = 0; j < hb->nq + 1; j++)
        hb->qw[j] = c->base[j] + lambda * hb->dy[j];
    int status = corrector_evaluate(c);
    *accept = status == FRICREG_OK &&
              (c->converged || fr_armijo_decrease(c->ls, c->prev, c->norm, lambda));
    return status;
}

/* Newton's method on (R) bordered by border^T (y − anchor) = 0 from start into qw, with the
 * backtracking line search on |R| (Armijo's condition, FR_HB_HALVINGS halvings, as newton.c;
 * past them the shortest trial: the iteration bound ends it): at a kink of the branch, where
 * the stick/slip or contact pattern changes, the plain iteration may cycle. *its the
 * iterations, b->delta and b->kappa the first step's length and the second's ratio to it. On
 * success A holds the bordered matrix at qw, unfactored (tangent_from_matrix). */
static int corrector(fricreg_hb *hb, const char *fn, struct branch *b, const double *start,
                     const double *anchor, const double *border, int *its)
{
    size_t ld = hb->nq + 1;
    struct fr_line_search ls = {FR_ARMIJO, FR_HB_HALVINGS, NULL};
    struct corrector_iterate c = {hb, fn, b, anchor, border, hb->yl, &ls, 0, 0, 0, 0, 0, 0};
    memcpy(hb->qw, start, ld * sizeof(double));
    b->delta = b->kappa = 0.0;
    int status = corrector_evaluate(&c);
    for (int it = 0;; it++) {
        if (status != FRICREG_OK)
            return status;
        if (it >= 1 && c.converged) {
            *its = it;
            return FRICREG_OK;
        }
        status = fr_hb_tick(hb, fn, fr_hb_parameter(hb), fmax(c.r / c.bound, fabs(c.g) / hb->tol));
        if (status != FRICREG_OK)
            return status;
        if (it == hb->max_iter)
            return fr_fail(hb, FRICREG_EWORK, "%s: the corrector did not converge in %d iterations",
                           fn, it);
        for (size_t j = 0; j < ld; j++)
            hb->dy[j] = -hb->R[j];
        if ((status = fr_hb_lu_solve(hb, fn, ld, hb->dy, hb->dy)) != FRICREG_OK)
            return status;
        double step = sqrt(dot(hb->dy, hb->dy, ld));
        if (it == 0)
            b->delta = step;
        else if (it == 1 && b->delta > 0.0)
            b->kappa = step / b->delta;
        memcpy(hb->yl, hb->qw, ld * sizeof(double));
        c.prev = c.norm;
        int accepted; /* none: on from the shortest trial, evaluated in qw */
        status = fr_line_search(&ls, 1.0, corrector_trial, &c, &accepted);
    }
}

/* The last step: the point at p1 by Newton at fixed parameter, from the direction's line
 * there; kept as the driver's solution. */
static int final_point(fricreg_hb *hb, const char *fn, const struct branch *b, double p1)
{
    size_t nq = hb->nq;
    double s = (p1 / b->ws - b->yc[nq]) / hb->dir[nq];
    double *guess = hb->rw; /* free here; fr_hb_solve_at copies it before it uses rw */
    for (size_t j = 0; j < nq; j++)
        guess[j] = (b->yc[j] + s * hb->dir[j]) * b->qs;
    if (b->level)
        hb->level = p1;
    int status = fr_hb_solve_at(hb, fn, omega_of(b, p1), guess, 1);
    if (status == FRICREG_OK)
        memcpy(hb->qt, hb->qw, nq * sizeof(double));
    return status;
}

/* The displacement scale follows the branch up: qs = the largest |q| so far, so that a branch
 * that starts far below a resonance takes steps in proportion to the amplitudes it reaches
 * (the points qw, yo and the tangent converted to the new scale). */
static void rescale(fricreg_hb *hb, struct branch *b)
{
    size_t nq = hb->nq;
    double top = 0.0;
    for (size_t j = 0; j < nq; j++)
        top = fmax(top, fabs(hb->qw[j]));
    if (!(top > 1.0))
        return;
    for (size_t j = 0; j < nq; j++) {
        hb->qw[j] /= top;
        b->yo[j] /= top;
        hb->tan[j] /= top;
    }
    double norm = sqrt(dot(hb->tan, hb->tan, nq + 1));
    for (size_t j = 0; j <= nq; j++)
        hb->tan[j] /= norm;
    b->qs *= top;
}

/* The new point y (scaled; yc the last point) runs back along the branch: within a tenth of
 * a step of an earlier stretch [point k − 1, point k], heading the same way (cosine > 1/2),
 * after a way along the branch since that stretch of more than 3 times the straight distance
 * (so not the branch's latest stretches, however it curves). */
static int doubles_back(const fricreg_hb *hb, const struct branch *b, const double *y)
{
    size_t nq = hb->nq, ld = nq + 1;
    double cq = 1.0 / b->qs, cw = 1.0 / b->ws, hs = dist(y, b->yc, ld), arc = hs;
    for (size_t k = hb->npts - 1; k >= 1; k--) {
        const double *p0 = hb->qpts + (k - 1) * ld, *p1 = hb->qpts + k * ld;
        double ll = 0.0, along = 0.0, same = 0.0, d0 = 0.0;
        for (size_t j = 0; j < ld; j++) {
            double c = j < nq ? cq : cw, e = (p1[j] - p0[j]) * c, r = y[j] - p0[j] * c;
            ll += e * e;
            along += e * r;
            same += e * (y[j] - b->yc[j]);
            d0 += r * r;
        }
        ll = sqrt(ll);
        arc += ll;
        if (!(ll > 0.0) || same <= 0.5 * ll * hs || arc <= 3.0 * (sqrt(d0) + ll))
            continue;
        double s = fmin(fmax(along / (ll * ll), 0.0), 1.0), d = 0.0;
        for (size_t j = 0; j < ld; j++) {
            double c = j < nq ? cq : cw, e = y[j] - (p0[j] + s * (p1[j] - p0[j])) * c;
            d += e * e;
        }
        if (sqrt(d) <= 0.1 * fmax(ll, hs))
            return 1;
    }
    return 0;
}

/* One step's outcome from yc with ds along dir: 0 accepted (qw the point, tn its tangent,
 * *alpha the angle between the tangents), 1 rejected (the message in b->why), or a status
 * that ends the continuation (FRICREG_ENOMEM). *sev is the converged corrector's severity,
 * max(κ/KAPPA_MAX, α/ALPHA_MAX) (above 1: rejected, unless a kink), 0 if it failed or left
 * the branch; sev_before the last rejected attempt's from the same point at twice the step. */
static int attempt(fricreg_hb *hb, const char *fn, struct branch *b, double ds, int *its,
                   double *alpha, double *sev, double sev_before, int *kink)
{
    size_t nq = hb->nq, ld = nq + 1;
    for (size_t j = 0; j < ld; j++)
        b->yp[j] = b->yc[j] + ds * hb->dir[j];
    *alpha = *sev = 0.0;
    *kink = 0;
    int status = corrector(hb, fn, b, b->yp, b->yp, hb->dir, its);
    if (status == FRICREG_OK)
        status = tangent_from_matrix(hb, fn, hb->tn);
    if (status == FRICREG_ENOMEM || hb->stopped)
        return status;
    if (status != FRICREG_OK) {
        snprintf(b->why, sizeof b->why, "%s", hb->err.msg);
        return -1;
    }
    double h = dist(hb->qw, b->yc, ld), deg = 57.29577951308232;
    *alpha = acos(fmax(-1.0, fmin(1.0, dot(hb->tn, hb->tan, ld))));
    if (h > JUMP * ds) {
        snprintf(b->why, sizeof b->why,
                 "%s: the corrector ended %g from the last point, beyond %g ds = %g", fn, h, JUMP,
                 JUMP * ds);
        return -1;
    }
    /* on a smooth arc the chord lies half way between the tangents, at a kink between them:
     * a chord that turned by much more than the tangents did joined another part of the
     * branch (two flanks of a sharp peak, nearly parallel, a tiny Ω apart) */
    double chord = acos(
        fmax(-1.0, fmin(1.0, (dot(hb->qw, hb->tan, ld) - dot(b->yc, hb->tan, ld)) / h)));
    if (chord > 2.0 * *alpha + CHORD_SLACK) {
        snprintf(b->why, sizeof b->why,
                 "%s: the chord turned by %.3g degrees from the tangent, which turned by %.3g", fn,
                 chord * deg, *alpha * deg);
        return -1;
    }
    /* a slow corrector (its first steps contract by more than KAPPA_MAX: the predictor was
     * far from where Newton converges fast, or it converged to another part of the branch)
     * or a tangent turned by more than ALPHA_MAX: the step was too long for the branch's
     * curvature. On a smooth branch both fall in proportion to ds; if they did not fall by a
     * quarter when ds was halved, this is a kink of the branch: accepted. */
    *sev = fmax(*alpha / ALPHA_MAX, b->kappa / KAPPA_MAX);
    if (*sev <= 1.0)
        return 0;
    if (sev_before > 0.0 && *sev >= 0.75 * sev_before && *alpha < KINK_MAX) {
        *kink = 1;
        return 0;
    }
    if (*alpha > ALPHA_MAX)
        snprintf(b->why, sizeof b->why, "%s: the tangent turned by %.3g degrees, beyond %.3g", fn,
                 *alpha * deg, ALPHA_MAX * deg);
    else
        snprintf(b->why, sizeof b->why,
                 "%s: the corrector's first steps contracted by %.3g, beyond %.3g", fn, b->kappa,
                 KAPPA_MAX);
    return -1;
}

static int follow(fricreg_hb *hb, const char *fn, struct branch *b, double p1)
{
    size_t nq = hb->nq, ld = nq + 1;
    double ds = hb->ds0, dir = p1 > b->yc[nq] * b->ws ? 1.0 : -1.0;
    /* the first tangent, bordered by the direction of p1 */
    memset(hb->dir, 0, ld * sizeof(double));
    hb->dir[nq] = dir;
    int status = bordered(hb, fn, b, b->yc, hb->dir);
    if (status == FRICREG_OK)
        status = tangent_from_matrix(hb, fn, hb->tan);
    if (status != FRICREG_OK)
        return status;
    if (b->keep) { /* the first point's tangent and determinant */
        hb->xpts[0] = hb->tan[nq];
        hb->xpts[1] = det_sign(hb, ld);
    }
    for (;;) {
        if (b->count >= hb->max_points)
            return fr_fail(hb, FRICREG_EWORK, "%s: %zu points stored before %s1 = %g", fn, b->count,
                           b->par, p1);
        /* the step from yc: along the tangent, halved on rejection; below ds_min once more
         * along the secant of the last two points (the tangent of a non-smooth Jacobian may
         * point off the branch), from the last accepted step */
        int its = 0, kink = 0, secant = 0, accepted = 0, last = 0;
        double alpha = 0.0, sev = 0.0, sev_before = 0.0, ds_start = ds;
        memcpy(hb->dir, hb->tan, ld * sizeof(double));
        while (!accepted) {
            for (size_t j = 0; j <= nq; j++)
                b->yp[j] = b->yc[j] + ds * hb->dir[j];
            last = dir * (b->yp[nq] * b->ws - p1) >= 0.0;
            if (last) {
                status = final_point(hb, fn, b, p1);
                if (status == FRICREG_OK)
                    break;
                if (status == FRICREG_ENOMEM || hb->stopped)
                    return status;
                snprintf(b->why, sizeof b->why, "%s", hb->err.msg);
                last = 0;
            } else {
                int r = attempt(hb, fn, b, ds, &its, &alpha, &sev, sev_before, &kink);
                if (r > 0)
                    return r;
                if (r == 0) {
                    accepted = 1;
                    break;
                }
                sev_before = sev; /* 0 unless the corrector converged near the branch */
            }
            /* a converged corrector near the last point whose tangent turned (but not
             * back) is a solution: accepted rather than the step halved below ds_min */
            if (sev > 0.0 && alpha < KINK_MAX && 0.5 * ds < hb->ds_min) {
                kink = accepted = 1;
                break;
            }
            ds *= 0.5;
            if (ds >= hb->ds_min)
                continue;
            if (secant || !b->have_prev)
                return fr_fail(hb, FRICREG_EINTEGRATOR,
                               "%s: the step fell below ds_min = %g at %s = %g (last failure: %s)",
                               fn, hb->ds_min, b->par, b->yc[nq] * b->ws, b->why);
            secant = 1;
            double h = dist(b->yc, b->yo, ld);
            for (size_t j = 0; j < ld; j++)
                hb->dir[j] = (b->yc[j] - b->yo[j]) / h;
            ds = ds_start;
            sev_before = 0.0;
        }
        if (last) /* the direction's sign and the last determinant's sign carried on */
            return store_point(hb, fn, b, p1, hb->dir[nq],
                               b->keep ? hb->xpts[(hb->npts - 1) * hb->xpts_stride + 1] : 0.0, 1);
        if (b->keep && doubles_back(hb, b, hb->qw))
            return fr_fail(hb, FRICREG_EWORK,
                           "%s: the branch doubles back on itself at %s = %g (after %zu "
                           "points): it would not reach %s1 = %g",
                           fn, b->par, hb->qw[nq] * b->ws, hb->npts, b->par, p1);
        /* bordered() left qt, the factors, the forces and the level at qw */
        status = store_point(hb, fn, b, hb->qw[nq] * b->ws, hb->tn[nq], det_sign(hb, ld), 0);
        if (status != FRICREG_OK)
            return status;
        memcpy(b->yo, b->yc, ld * sizeof(double));
        b->have_prev = 1;
        memcpy(hb->tan, hb->tn, ld * sizeof(double));
        rescale(hb, b);
        memcpy(b->yc, hb->qw, ld * sizeof(double));
        /* the next step: Allgower & Georg's factor on the corrector and the angle */
        double f = fmax(fmax(b->kappa / KAPPA0, b->delta / (ds * DELTA0)),
                        fmax(kink ? 0.0 : alpha / ALPHA0, its / ITS0));
        f = fmin(fmax(f, 0.5), 2.0);
        ds = fmin(fmax(ds / f, hb->ds_min), hb->ds_max);
    }
}

/* ---- Bifurcations between the stored points ---------------------------------------------- */

/* A bifurcation's test: its type, and for a change of stability the exponents' kind it follows
 * (fr_hb_hill_unstable). */
struct test {
    int type, kind;
};

/* The test's sign (0 or 1) at a point whose extras are x (xpts's layout) at omega. */
static int test_sign(const fricreg_hb *hb, struct test t, const double *x, double omega)
{
    if (t.kind >= 0)
        return fr_hb_hill_unstable(hb, omega, x + 4, t.kind);
    return x[t.type == FRICREG_HB_TP ? 0 : 1] > 0.0;
}

/* The branch's point on the hyperplane normal to the chord ya → yb (scaled) through
 * ya + s (yb − ya): its test sign, Ω, and the RMS of each dof into rms. */
static int test_at(fricreg_hb *hb, struct branch *b, const double *ya, const double *yb, double s,
                   struct test t, int *sign, double *omega, double *rms)
{
    static const char fn[] = "continue";
    size_t nq = hb->nq, ld = nq + 1;
    double *normal = hb->dir, *anchor = hb->yo, len = dist(yb, ya, ld);
    for (size_t j = 0; j < ld; j++) {
        normal[j] = (yb[j] - ya[j]) / len;
        anchor[j] = ya[j] + s * (yb[j] - ya[j]);
    }
    int its = 0, status = corrector(hb, fn, b, anchor, anchor, normal, &its);
    if (status != FRICREG_OK)
        return status;
    *omega = omega_of(b, hb->qw[nq] * b->ws);
    double tx[2], *x = t.kind >= 0 ? hb->hill_x : tx;
    if (t.kind >= 0)
        status = fr_hb_hill(hb, fn, *omega, x + 2);
    else if ((status = tangent_from_matrix(hb, fn, hb->rw)) == FRICREG_OK) {
        x[0] = hb->rw[nq];
        x[1] = det_sign(hb, ld);
    }
    if (status != FRICREG_OK)
        return status;
    *sign = test_sign(hb, t, x, *omega);
    fr_hb_rms(hb, rms); /* bordered() left the factors and forces at qw */
    return FRICREG_OK;
}

/* Bisection on the test's sign between stored points k and k + 1, to 1e-9 of their chord; the
 * bifurcation recorded at the last bracket's middle (or, should a trial fail, at the bracket's
 * end nearer to the points' side it came from). */
static void bisect(fricreg_hb *hb, struct branch *b, size_t k, struct test t)
{
    size_t ld = hb->nq + 1, n = hb->n, xw = hb->xpts_stride;
    double *ya = hb->yp, *yb = hb->yp + ld, lo = 0.0, hi = 1.0;
    for (size_t j = 0; j < ld; j++) {
        double c = j < hb->nq ? b->qs : b->ws;
        ya[j] = hb->qpts[k * ld + j] / c;
        yb[j] = hb->qpts[(k + 1) * ld + j] / c;
    }
    /* a change of stability's side at point k is its verdict's (an exponent within the
     * verdict's margin of the unit circle there puts the crossing at k itself) */
    const double *xk = hb->xpts + k * xw;
    int sa = t.kind >= 0 ? xk[2] == 0.0 : test_sign(hb, t, xk, hb->pts[k * (1 + n)]);
    double *rec = hb->bifs + hb->nbif * (4 + n);
    rec[0] = t.type;
    rec[2] = (double)k;
    double omega = 0.0;
    int found = 0;
    while (hi - lo > 1e-9) {
        double s = 0.5 * (lo + hi);
        int sign = 0;
        if (test_at(hb, b, ya, yb, s, t, &sign, &omega, rec + 4) != FRICREG_OK) {
            if (hb->stopped) /* no bifurcation recorded: the call ends */
                return;
            break;
        }
        rec[1] = omega;
        rec[3] = hb->level; /* corrector() left the trial's */
        found = 1;
        if (sign == sa)
            lo = s;
        else
            hi = s;
    }
    if (!found) { /* the stored point nearer to the bracket */
        size_t at = lo > 0.0 ? k + 1 : k;
        rec[1] = hb->pts[at * (1 + n)];
        rec[3] = b->level ? hb->qpts[at * ld + hb->nq] : 1.0;
        memcpy(rec + 4, hb->pts + at * (1 + n) + 1, n * sizeof(double));
    }
    hb->nbif++;
}

/* Each pair of successive points: the first test whose sign changed, located. */
static void locate_bifurcations(fricreg_hb *hb, struct branch *b)
{
    size_t xw = hb->xpts_stride, w = 1 + hb->n;
    hb->nbif = 0;
    for (size_t k = 0; k + 1 < hb->npts && !hb->stopped; k++) {
        const double *x0 = hb->xpts + k * xw, *x1 = x0 + xw;
        struct test t = {0, -1};
        if ((x0[0] > 0.0) != (x1[0] > 0.0))
            t.type = FRICREG_HB_TP;
        else if (x0[1] * x1[1] < 0.0)
            t.type = FRICREG_HB_BP;
        else if (hb->stability && x0[2] != x1[2]) {
            /* the exponent that crossed: the largest on the unstable side */
            int up = x1[2] == 0.0;
            const double *xu = up ? x1 : x0;
            t.kind = fr_hb_hill_crossing(hb, hb->pts[(k + (size_t)up) * w], xu + 4);
            t.type = t.kind == 1 ? FRICREG_HB_PD : t.kind == 2 ? FRICREG_HB_NS : FRICREG_HB_BP;
        }
        if (t.type != 0)
            bisect(hb, b, k, t);
    }
}

size_t fricreg_hb_bifurcations(const fricreg_hb *hb)
{
    return hb ? hb->nbif : 0;
}

int fricreg_hb_bifurcation(fricreg_hb *hb, size_t i, int *type, double *omega, size_t *point,
                           size_t ndof, double rms[])
{
    static const char fn[] = "bifurcation";
    if (hb == NULL)
        return FRICREG_ENULL;
    if (type == NULL || omega == NULL || rms == NULL)
        return fr_fail(hb, FRICREG_ENULL, "%s: %s is NULL", fn,
                       type == NULL    ? "type"
                       : omega == NULL ? "omega"
                                       : "rms");
    if (i >= hb->nbif)
        return fr_fail(hb, FRICREG_EINVAL, "%s: i = %zu, %zu bifurcations located", fn, i,
                       hb->nbif);
    if (ndof != hb->n)
        return fr_fail(hb, FRICREG_ESIZE, "%s: ndof = %zu, the driver has %zu", fn, ndof, hb->n);
    const double *rec = hb->bifs + i * (4 + hb->n);
    *type = (int)rec[0];
    *omega = rec[1];
    if (point != NULL)
        *point = (size_t)rec[2];
    memcpy(rms, rec + 4, hb->n * sizeof(double));
    return FRICREG_OK;
}

/* The branch of b's parameter from p0 to p1 (b's kind, Ω and keep set), its first point solved
 * from q0 (NULL: fr_hb_solve_at's guesses); with keep the points stored (the earlier ones
 * dropped) and the bifurcations between them located. The scales: qs the first point's
 * displacement scale (raised along the branch), ws = |p1 − p0|. */
static int run(fricreg_hb *hb, const char *fn, struct branch *b, double p0, double p1,
               const double *q0)
{
    size_t nq = hb->nq;
    /* the first 64 points' room before anything changes: a failure here changes nothing */
    int status = b->keep ? reserve(hb, 64) : FRICREG_OK;
    if (status != FRICREG_OK)
        return status;
    if (b->keep) {
        hb->npts = 0;
        hb->nbif = 0;
        hb->have_branch = 1;
        hb->branch_level = b->level;
    }
    if (b->level)
        hb->level = p0;
    if ((status = fr_hb_solve_at(hb, fn, omega_of(b, p0), q0, b->keep)) != FRICREG_OK)
        return status;
    b->ws = fabs(p1 - p0);
    b->yc = hb->yp;
    b->yp = hb->yp + nq + 1;
    b->yo = hb->yo;
    b->qs = fr_hb_scale(hb, hb->qw);
    memcpy(hb->qt, hb->qw, nq * sizeof(double));
    if ((status = store_point(hb, fn, b, p0, 0.0, 0.0, 1)) != FRICREG_OK)
        return status;
    for (size_t j = 0; j < nq; j++)
        b->yc[j] = hb->qw[j] / b->qs;
    b->yc[nq] = p0 / b->ws;
    struct fr_error before = hb->err; /* a success keeps it: the halved steps' failures are not
                                         the call's */
    status = follow(hb, fn, b, p1);
    if (b->keep) {
        hb->branch_qs = b->qs;
        hb->branch_ws = b->ws;
        struct fr_error after = hb->err; /* the bisections' failed trials are not the call's */
        locate_bifurcations(hb, b);
        hb->err = after;
    }
    if (status == FRICREG_OK)
        hb->err = before;
    return status;
}

int fricreg_hb_continue(fricreg_hb *hb, double omega0, double omega1, size_t nq, const double q0[])
{
    if (hb == NULL)
        return FRICREG_ENULL;
    const char *fn = "continue";
    if (hb->busy)
        return fr_hb_busy(hb, fn);
    int status = fr_hb_check_start(hb, fn, omega0, nq, q0);
    if (status == FRICREG_OK && !isfinite(omega1))
        status = fr_fail(hb, FRICREG_ENONFINITE, "%s: Omega1 = %g", fn, omega1);
    if (status == FRICREG_OK && (!(omega1 > 0.0) || omega1 == omega0))
        status = fr_fail(hb, FRICREG_EINVAL, "%s: Omega1 = %g must be > 0 and differ from %g", fn,
                         omega1, omega0);
    if (status != FRICREG_OK)
        return status;
    struct fr_error before = hb->err; /* a success keeps it: a failed start is not the call's */
    fr_hb_begin(hb, 1);
    if (q0 == NULL) {
        /* from fricreg_hb_solve's solution without a guess; should that fail, the plain
         * guesses at omega0 once more, for their message */
        status = fr_hb_default_start(hb, fn, omega0);
        if (status == FRICREG_ENOMEM)
            return fr_hb_end(hb, status);
        if (status == FRICREG_OK)
            q0 = hb->qsol;
    }
    struct branch b = {.par = "Omega", .keep = 1};
    status = fr_hb_end(hb, run(hb, fn, &b, omega0, omega1, q0));
    if (status == FRICREG_OK)
        hb->err = before;
    return status;
}

int fricreg_hb_continue_level(fricreg_hb *hb, double omega, double level0, double level1, size_t nq,
                              const double q0[])
{
    if (hb == NULL)
        return FRICREG_ENULL;
    const char *fn = "continue_level";
    if (hb->busy)
        return fr_hb_busy(hb, fn);
    int status = fr_hb_check_start(hb, fn, omega, nq, q0);
    if (status == FRICREG_OK && (!isfinite(level0) || !isfinite(level1)))
        status = fr_fail(hb, FRICREG_ENONFINITE, "%s: level0 = %g, level1 = %g", fn, level0,
                         level1);
    if (status == FRICREG_OK && (!(level0 >= 0.0) || !(level1 >= 0.0) || level0 == level1))
        status = fr_fail(hb, FRICREG_EINVAL,
                         "%s: level0 = %g and level1 = %g must be >= 0 and differ", fn, level0,
                         level1);
    if (status != FRICREG_OK)
        return status;
    struct branch b = {.level = 1, .omega = omega, .par = "level", .keep = 1};
    fr_hb_begin(hb, 0);
    status = run(hb, fn, &b, level0, level1, q0);
    hb->level = 1.0; /* the excitation as set, for the calls to come */
    return fr_hb_end(hb, status);
}

/* The excitation level where fricreg_hb_solve's start begins: small enough for every element
 * to stay in the regime of the stuck guess (a Jenkins element slips once kt |q| > mu N, its
 * q proportional to λ there), not so small that the first point's tolerance, relative to
 * the response, reaches rounding. */
#define LEVEL_START 1e-3

/* Whether the old start's solution q1 at λ = 1 lies on the branch from the linear regime:
 * with q0 the solution at λ = 0 (every element in its regime of no load: stuck, or closed
 * under a preload, or open across a gap), the line q0 + λ (q1 − q0) solves (R) at λ = 1e-3 to
 * Newton's tolerance, so the elements are in that same regime at both ends; a regime is a set
 * of linear inequalities in λ along the line (|kt (u − w)| <= mu N for some w, N0 + kn g >= 0
 * or <= 0), so it holds between them, and the line is the branch. Scratch: tan, tn. */
static int on_linear_branch(fricreg_hb *hb, const char *fn, double omega, int *yes)
{
    size_t nq = hb->nq;
    double *q0 = hb->tan, *q1 = hb->tn, s0, s1;
    *yes = 0;
    hb->level = 0.0;
    int status = fr_hb_solve_at(hb, fn, omega, NULL, 0);
    if (status != FRICREG_OK)
        return status;
    memcpy(q0, hb->qw, nq * sizeof(double));
    s0 = fr_hb_scale(hb, q0);
    hb->level = 1.0;
    if ((status = fr_hb_solve_at(hb, fn, omega, NULL, 0)) != FRICREG_OK)
        return status;
    memcpy(q1, hb->qw, nq * sizeof(double));
    s1 = fr_hb_scale(hb, q1);
    hb->level = LEVEL_START;
    for (size_t j = 0; j < nq; j++)
        hb->qt[j] = q0[j] + LEVEL_START * (q1[j] - q0[j]);
    if ((status = fr_hb_residual(hb, fn, hb->qt, hb->R, 0)) != FRICREG_OK)
        return status;
    /* (R) there is (1 − λ) R(q0) + λ R(q1) when the forces are affine along the line */
    double r = 0.0, bound = hb->tol *
                            ((1.0 - LEVEL_START) * s0 + LEVEL_START * s1 + fr_hb_scale(hb, hb->qt));
    for (size_t j = 0; j < nq; j++)
        r = fmax(r, fabs(hb->R[j]));
    *yes = r <= bound;
    return FRICREG_OK;
}

/* The branch in the excitation level at omega from the linear regime to λ = 1, the solution
 * kept as fr_hb_solve_at's (fricreg_hb_solve's docstring). */
static int level_start(fricreg_hb *hb, const char *fn, double omega)
{
    /* the old start, when its solution is the branch's: its Newton once more to keep it */
    int linear = 0, status = on_linear_branch(hb, fn, omega, &linear);
    hb->level = 1.0;
    if (status == FRICREG_OK && linear)
        return fr_hb_solve_at(hb, fn, omega, hb->tn, 1);
    if (status == FRICREG_ENOMEM || hb->stopped)
        return status;
    struct branch b = {.level = 1, .omega = omega, .par = "level"};
    status = run(hb, fn, &b, LEVEL_START, 1.0, NULL);
    hb->level = 1.0;
    return status;
}

/* The nearby frequencies of the frequency start, omega (1 + d) then omega / (1 + d) for each
 * d, nearest first: far enough apart that a resonance's width (ζ of a few per cent) is left. */
static const double START_OFFSETS[] = {0.05, 0.1, 0.2, 0.4, 0.8};
#define START_TRIALS (2 * sizeof START_OFFSETS / sizeof START_OFFSETS[0])

/* The branch in Ω to omega from the nearest frequency of START_OFFSETS where the plain guesses
 * converge: for a response homogeneous in the forcing (a unilateral spring without gap or
 * preload) the level's branch is a ray, its every point as hard to reach as its end. One
 * continuation at most, its points not stored. */
static int frequency_start(fricreg_hb *hb, const char *fn, double omega)
{
    int status = FRICREG_EWORK;
    for (size_t i = 0; i < START_TRIALS; i++) {
        double d = START_OFFSETS[i / 2], from = i % 2 ? omega / (1.0 + d) : omega * (1.0 + d);
        status = fr_hb_solve_at(hb, fn, from, NULL, 0);
        if (status == FRICREG_ENOMEM || hb->stopped)
            return status;
        if (status == FRICREG_OK) {
            struct branch b = {.par = "Omega"};
            return run(hb, fn, &b, from, omega, NULL);
        }
    }
    return status;
}

int fr_hb_default_start(fricreg_hb *hb, const char *fn, double omega)
{
    int status = level_start(hb, fn, omega);
    if (status == FRICREG_OK || status == FRICREG_ENOMEM || hb->stopped)
        return status;
    if ((status = fr_hb_solve_at(hb, fn, omega, NULL, 1)) == FRICREG_OK ||
        status == FRICREG_ENOMEM || hb->stopped)
        return status;
    struct fr_error plain = hb->err; /* the failure reported should all three fail */
    int plain_status = status;
    if ((status = frequency_start(hb, fn, omega)) == FRICREG_OK || status == FRICREG_ENOMEM ||
        hb->stopped)
        return status;
    hb->err = plain;
    return plain_status;
}

size_t fricreg_hb_points(const fricreg_hb *hb)
{
    return hb ? hb->npts : 0;
}

int fricreg_hb_point(fricreg_hb *hb, size_t k, double *omega, size_t ndof, double rms[])
{
    if (hb == NULL)
        return FRICREG_ENULL;
    if (omega == NULL || rms == NULL)
        return fr_fail(hb, FRICREG_ENULL, "point: %s is NULL", omega == NULL ? "omega" : "rms");
    if (k >= hb->npts)
        return fr_fail(hb, FRICREG_EINVAL, "point: k = %zu, %zu points stored", k, hb->npts);
    if (ndof != hb->n)
        return fr_fail(hb, FRICREG_ESIZE, "point: ndof = %zu, the driver has %zu", ndof, hb->n);
    const double *p = hb->pts + k * (1 + hb->n);
    *omega = p[0];
    memcpy(rms, p + 1, hb->n * sizeof(double));
    return FRICREG_OK;
}

int fricreg_hb_point_level(fricreg_hb *hb, size_t k, double *level)
{
    if (hb == NULL)
        return FRICREG_ENULL;
    if (level == NULL)
        return fr_fail(hb, FRICREG_ENULL, "point_level: level is NULL");
    if (k >= hb->npts)
        return fr_fail(hb, FRICREG_EINVAL, "point_level: k = %zu, %zu points stored", k, hb->npts);
    *level = hb->branch_level ? hb->qpts[k * hb->qpts_stride + hb->qpts_stride - 1] : 1.0;
    return FRICREG_OK;
}

int fricreg_hb_bifurcation_level(fricreg_hb *hb, size_t i, double *level)
{
    if (hb == NULL)
        return FRICREG_ENULL;
    if (level == NULL)
        return fr_fail(hb, FRICREG_ENULL, "bifurcation_level: level is NULL");
    if (i >= hb->nbif)
        return fr_fail(hb, FRICREG_EINVAL, "bifurcation_level: i = %zu, %zu bifurcations located",
                       i, hb->nbif);
    *level = hb->bifs[i * (4 + hb->n) + 3];
    return FRICREG_OK;
}

/* Dof k's RMS at the branch's point on the hyperplane border^T (y − anchor) = 0, from start
 * (scaled, b's scales); Ω into *omega. */
static int rms_on_plane(fricreg_hb *hb, struct branch *b, size_t k, const double *start,
                        const double *anchor, const double *border, double *omega, double *f)
{
    int its = 0, status = corrector(hb, "peak", b, start, anchor, border, &its);
    if (status != FRICREG_OK)
        return status;
    *omega = hb->qw[hb->nq] * b->ws;
    *f = fr_hb_rms_dof(hb, k); /* bordered() left the factors and forces at qw */
    return FRICREG_OK;
}

/* The point of the branch at s in [0, 1] along the chord from ya to yc: its hyperplane (normal
 * the chord, through ya + s (yc − ya)) and the quadratic through ya, yb, yc (at 0, sb, 1) as
 * the corrector's start; dof k's RMS there. */
static int rms_at(fricreg_hb *hb, struct branch *b, size_t k, const double *y3[3], double sb,
                  double s, double *omega, double *f)
{
    size_t ld = hb->nq + 1;
    double *normal = hb->dir, *anchor = hb->yo, *start = hb->tn, len = dist(y3[2], y3[0], ld);
    double la = (s - sb) * (s - 1.0) / sb, lb = s * (s - 1.0) / (sb * (sb - 1.0)),
           lc = s * (s - sb) / (1.0 - sb);
    for (size_t j = 0; j < ld; j++) {
        normal[j] = (y3[2][j] - y3[0][j]) / len;
        anchor[j] = y3[0][j] + s * (y3[2][j] - y3[0][j]);
        start[j] = la * y3[0][j] + lb * y3[1][j] + lc * y3[2][j];
    }
    return rms_on_plane(hb, b, k, start, anchor, normal, omega, f);
}

/* Brent's minimization without derivatives (R. P. Brent, "Algorithms for Minimization without
 * Derivatives", Prentice-Hall 1973, Ch. 5: golden section and successive parabolic
 * interpolation) of −RMS over s in [0, 1], from x = sb where RMS is at least its value at 0 and
 * 1; s to 1e-6 (the RMS to about 1e-12 of itself, below Newton's tolerance). */
static int brent_peak(fricreg_hb *hb, struct branch *b, size_t k, const double *y3[3], double sb,
                      double fb, double *omega, double *rms)
{
    const double golden = 0.3819660112501051, tol1 = 1e-6;
    double a = 0.0, c = 1.0, x = sb, w = sb, v = sb, fx = -fb, fw = fx, fv = fx, d = 0.0, e = 0.0;
    for (int evals = 0; evals < 60; evals++) {
        double xm = 0.5 * (a + c), tol2 = 2.0 * tol1;
        if (fabs(x - xm) <= tol2 - 0.5 * (c - a))
            break;
        int parabolic = 0;
        if (fabs(e) > tol1) {
            double r = (x - w) * (fx - fv), q = (x - v) * (fx - fw), p = (x - v) * q - (x - w) * r;
            q = 2.0 * (q - r);
            if (q > 0.0)
                p = -p;
            q = fabs(q);
            double last = e;
            e = d;
            if (fabs(p) < fabs(0.5 * q * last) && p > q * (a - x) && p < q * (c - x)) {
                d = p / q;
                parabolic = 1;
                double u = x + d;
                if (u - a < tol2 || c - u < tol2)
                    d = xm >= x ? tol1 : -tol1;
            }
        }
        if (!parabolic) {
            e = x >= xm ? a - x : c - x;
            d = golden * e;
        }
        double u = fabs(d) >= tol1 ? x + d : x + (d >= 0.0 ? tol1 : -tol1), om = 0.0, fu = 0.0;
        int status = rms_at(hb, b, k, y3, sb, u, &om, &fu);
        if (status != FRICREG_OK)
            return status;
        fu = -fu;
        if (fu <= fx) {
            if (u >= x)
                a = x;
            else
                c = x;
            v = w, fv = fw, w = x, fw = fx, x = u, fx = fu;
            *omega = om;
        } else {
            if (u < x)
                a = u;
            else
                c = u;
            if (fu <= fw || w == x)
                v = w, fv = fw, w = u, fw = fu;
            else if (fu <= fv || v == x || v == w)
                v = u, fv = fu;
        }
    }
    *rms = -fx;
    return FRICREG_OK;
}

int fricreg_hb_peak(fricreg_hb *hb, size_t dof, double *omega, double *rms)
{
    if (hb == NULL)
        return FRICREG_ENULL;
    if (omega == NULL || rms == NULL)
        return fr_fail(hb, FRICREG_ENULL, "peak: %s is NULL", omega == NULL ? "omega" : "rms");
    if (hb->busy)
        return fr_hb_busy(hb, "peak");
    if (dof >= hb->n)
        return fr_fail(hb, FRICREG_EINVAL, "peak: dof = %zu, the driver has %zu", dof, hb->n);
    if (hb->npts == 0 || !hb->have_branch)
        return fr_fail(hb, FRICREG_EINVAL,
                       "peak: no branch (no fricreg_hb_continue yet, or the model changed since)");
    if (hb->branch_level)
        return fr_fail(hb, FRICREG_EINVAL,
                       "peak: the branch is in the excitation level (fricreg_hb_continue_level), "
                       "not in Omega");
    size_t w = 1 + hb->n, ld = hb->nq + 1, best = 0;
    for (size_t k = 1; k < hb->npts; k++)
        if (hb->pts[k * w + 1 + dof] > hb->pts[best * w + 1 + dof])
            best = k;
    double om = hb->pts[best * w], f = hb->pts[best * w + 1 + dof];
    if (best > 0 && best + 1 < hb->npts) {
        /* the three points around it, scaled */
        struct branch b = {.qs = hb->branch_qs, .ws = hb->branch_ws};
        double *y[3] = {hb->yp, hb->yp + ld, hb->tan};
        for (int i = 0; i < 3; i++)
            for (size_t j = 0; j < ld; j++)
                y[i][j] = hb->qpts[(best - 1 + (size_t)i) * ld + j] / (j + 1 < ld ? b.qs : b.ws);
        const double *y3[3] = {y[0], y[1], y[2]};
        double len = dist(y[2], y[0], ld), sb = 0.0;
        for (size_t j = 0; j < ld; j++)
            sb += (y[1][j] - y[0][j]) * (y[2][j] - y[0][j]) / (len * len);
        /* the middle point projects inside the chord (the tangent turns by less than 90° a
         * step): otherwise the sampled point stands */
        if (sb > 0.0 && sb < 1.0) {
            struct fr_error before = hb->err;
            fr_hb_begin(hb, 1);
            int status = fr_hb_end(hb, brent_peak(hb, &b, dof, y3, sb, f, &om, &f));
            if (status != FRICREG_OK)
                return status;
            hb->err = before;
        }
    }
    *omega = om;
    *rms = f;
    return FRICREG_OK;
}
