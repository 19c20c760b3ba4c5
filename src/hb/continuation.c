/* SPDX-License-Identifier: GPL-3.0-or-later */
/* continuation.c — the frequency response by pseudo-arclength continuation (H. B. Keller,
 * "Numerical solution of bifurcation and nonlinear eigenvalue problems", 1977; Krack & Gross
 * 2019, Ch. 5) on the scaled unknowns y = (q/qs, Ω/ws), qs the starting solution's displacement
 * scale raised to the largest |q| the branch reaches, ws = |Ω1 − Ω0|: the tangent t from [R_q R_Ω; t_prev^T] t = [0; 1], normalized; the
 * predictor y + ds t; the corrector Newton's method on (R) bordered by t^T (y − y_pred) = 0; the
 * step grown by 1.5 after a quick corrector, halved after a failed one or one that ended
 * farther than ds/2 from its predictor. The points' Ω and RMS
 * are stored, and the getters. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hb_internal.h"

struct branch {
    double qs, ws; /* the scales */
    double *yc;    /* [nq + 1] the last point, scaled */
    double *yp;    /* [nq + 1] the predictor */
    char why[256]; /* the last failed step's message */
};

/* Room for `want` points (at most max_points), kept on failure: FRICREG_ENOMEM. */
static int reserve(fricreg_hb *hb, size_t want)
{
    if (want > hb->max_points)
        want = hb->max_points;
    if (want <= hb->cap)
        return FRICREG_OK;
    double *p = realloc(hb->pts, want * (1 + hb->n) * sizeof(double));
    if (p == NULL)
        return fr_fail(hb, FRICREG_ENOMEM, "continue: no memory for %zu points", want);
    hb->pts = p;
    hb->cap = want;
    return FRICREG_OK;
}

static int store_point(fricreg_hb *hb, double omega)
{
    size_t w = 1 + hb->n;
    int status = hb->npts < hb->cap ? FRICREG_OK : reserve(hb, 2 * hb->cap);
    if (status != FRICREG_OK)
        return status;
    hb->pts[hb->npts * w] = omega;
    fr_hb_rms(hb, hb->pts + hb->npts * w + 1);
    hb->npts++;
    memcpy(hb->qsol, hb->qt, hb->nq * sizeof(double));
    hb->omega_sol = omega;
    hb->have_solution = 1;
    return FRICREG_OK;
}

/* Residual (scaled) at y into R[nq + 1] (the arclength equation last, when yp is given) and
 * the bordered matrix into A: [R_q, R_Ω ws/qs; row^T]. qt holds the unscaled q. */
static int bordered(fricreg_hb *hb, const char *fn, const struct branch *b, const double *y,
                    const double *row)
{
    size_t nq = hb->nq, ld = nq + 1;
    double omega = y[nq] * b->ws;
    if (!(omega > 0.0))
        return fr_fail(hb, FRICREG_EINVAL, "%s: the branch reached Omega = %g <= 0", fn, omega);
    int status = fr_hb_factor(hb, fn, omega, 1);
    for (size_t j = 0; j < nq; j++)
        hb->qt[j] = y[j] * b->qs;
    if (status == FRICREG_OK)
        status = fr_hb_residual(hb, fn, hb->qt, hb->R, 1);
    if (status != FRICREG_OK)
        return status;
    fr_hb_domega(hb, hb->rw);
    fr_hb_matrix(hb, hb->jq, hb->A, ld);
    for (size_t j = 0; j < nq; j++) {
        hb->R[j] /= b->qs;
        hb->A[j * ld + nq] = hb->rw[j] * b->ws / b->qs;
    }
    memcpy(hb->A + nq * ld, row, ld * sizeof(double));
    return FRICREG_OK;
}

/* The unit tangent at yc into hb->tan, oriented along the previous one (hb->tan on entry). */
static int tangent(fricreg_hb *hb, const char *fn, const struct branch *b)
{
    size_t nq = hb->nq, ld = nq + 1;
    memcpy(hb->dy, hb->tan, ld * sizeof(double)); /* the previous tangent, the border */
    int status = bordered(hb, fn, b, b->yc, hb->dy);
    if (status != FRICREG_OK)
        return status;
    memset(hb->dy, 0, ld * sizeof(double));
    hb->dy[nq] = 1.0;
    if ((status = fr_hb_lu_solve(hb, fn, ld, hb->dy, hb->dy)) != FRICREG_OK)
        return status;
    double s = 0.0;
    for (size_t j = 0; j < ld; j++)
        s += hb->dy[j] * hb->dy[j];
    for (size_t j = 0; j < ld; j++)
        hb->tan[j] = hb->dy[j] / sqrt(s);
    return FRICREG_OK;
}

/* Newton's method on the bordered system from the predictor yp into qw; *its its iterations. */
static int corrector(fricreg_hb *hb, const char *fn, const struct branch *b, int *its)
{
    size_t nq = hb->nq, ld = nq + 1;
    memcpy(hb->qw, b->yp, ld * sizeof(double));
    for (int it = 0;; it++) {
        int status = bordered(hb, fn, b, hb->qw, hb->tan);
        if (status != FRICREG_OK)
            return status;
        double g = 0.0, r = 0.0;
        for (size_t j = 0; j < ld; j++)
            g += hb->tan[j] * (hb->qw[j] - b->yp[j]);
        hb->R[nq] = g;
        for (size_t j = 0; j < nq; j++)
            r = fmax(r, fabs(hb->R[j]));
        double bound = hb->tol * fr_hb_scale(hb, hb->qt) / b->qs;
        if (it >= 1 && r <= bound && fabs(g) <= hb->tol) {
            *its = it;
            return FRICREG_OK;
        }
        if (it == hb->max_iter)
            return fr_fail(hb, FRICREG_EWORK, "%s: the corrector did not converge in %d iterations",
                           fn, it);
        for (size_t j = 0; j < ld; j++)
            hb->dy[j] = -hb->R[j];
        if ((status = fr_hb_lu_solve(hb, fn, ld, hb->dy, hb->dy)) != FRICREG_OK)
            return status;
        for (size_t j = 0; j < ld; j++)
            hb->qw[j] += hb->dy[j];
    }
}

/* A corrector that ends farther than ds/2 from its predictor has left the branch's
 * neighbourhood (on a sharp peak the hyperplane t^T (y − y_pred) = 0 meets the branch again
 * beyond the peak, and Newton may go there): the step counts as failed, so it is halved. */
static int close_to_predictor(fricreg_hb *hb, const char *fn, const struct branch *b, double ds)
{
    double d = 0.0;
    for (size_t j = 0; j <= hb->nq; j++)
        d += (hb->qw[j] - b->yp[j]) * (hb->qw[j] - b->yp[j]);
    if (sqrt(d) > 0.5 * ds)
        return fr_fail(hb, FRICREG_EWORK,
                       "%s: the corrector ended %g from its predictor, beyond ds/2 = %g", fn,
                       sqrt(d), 0.5 * ds);
    return FRICREG_OK;
}

/* The last step: the point at omega1 by Newton at fixed Ω, from the tangent's line there. */
static int final_point(fricreg_hb *hb, const char *fn, const struct branch *b, double omega1)
{
    size_t nq = hb->nq;
    double s = (omega1 / b->ws - b->yc[nq]) / hb->tan[nq];
    double *guess = hb->rw; /* free here; fr_hb_solve_at copies it before it uses rw */
    for (size_t j = 0; j < nq; j++)
        guess[j] = (b->yc[j] + s * hb->tan[j]) * b->qs;
    int status = fr_hb_solve_at(hb, fn, omega1, guess);
    if (status == FRICREG_OK)
        memcpy(hb->qt, hb->qw, nq * sizeof(double));
    return status;
}

/* Halves ds after a failed step; FRICREG_EINTEGRATOR below ds_min. */
static int shrink(fricreg_hb *hb, const char *fn, struct branch *b, double *ds)
{
    snprintf(b->why, sizeof b->why, "%s", hb->err.msg);
    *ds *= 0.5;
    if (*ds < hb->ds_min)
        return fr_fail(hb, FRICREG_EINTEGRATOR,
                       "%s: the step fell below ds_min = %g at Omega = %g (last failure: %s)", fn,
                       hb->ds_min, b->yc[hb->nq] * b->ws, b->why);
    return FRICREG_OK;
}

/* The displacement scale follows the branch up: qs = the largest |q| so far, so that a branch
 * that starts far below a resonance takes steps in proportion to the amplitudes it reaches
 * (the point qw and the tangent converted to the new scale). */
static void rescale(fricreg_hb *hb, struct branch *b)
{
    size_t nq = hb->nq;
    double top = 0.0, norm = 0.0;
    for (size_t j = 0; j < nq; j++)
        top = fmax(top, fabs(hb->qw[j]));
    if (!(top > 1.0))
        return;
    for (size_t j = 0; j < nq; j++) {
        hb->qw[j] /= top;
        hb->tan[j] /= top;
    }
    for (size_t j = 0; j <= nq; j++)
        norm += hb->tan[j] * hb->tan[j];
    for (size_t j = 0; j <= nq; j++)
        hb->tan[j] /= sqrt(norm);
    b->qs *= top;
}

static int follow(fricreg_hb *hb, const char *fn, struct branch *b, double omega1)
{
    size_t nq = hb->nq;
    double ds = hb->ds0, dir = omega1 > b->yc[nq] * b->ws ? 1.0 : -1.0;
    memset(hb->tan, 0, (nq + 1) * sizeof(double));
    hb->tan[nq] = dir;
    for (;;) {
        if (hb->npts >= hb->max_points)
            return fr_fail(hb, FRICREG_EWORK, "%s: %zu points stored before Omega1 = %g", fn,
                           hb->npts, omega1);
        int status = tangent(hb, fn, b), its = 0;
        if (status != FRICREG_OK)
            return status;
        for (size_t j = 0; j <= nq; j++)
            b->yp[j] = b->yc[j] + ds * hb->tan[j];
        int last = dir * (b->yp[nq] * b->ws - omega1) >= 0.0;
        status = last ? final_point(hb, fn, b, omega1) : corrector(hb, fn, b, &its);
        if (status == FRICREG_OK && !last)
            status = close_to_predictor(hb, fn, b, ds);
        if (status == FRICREG_ENOMEM)
            return status;
        if (status != FRICREG_OK) {
            if ((status = shrink(hb, fn, b, &ds)) != FRICREG_OK)
                return status;
            continue;
        }
        double omega = last ? omega1 : hb->qw[nq] * b->ws;
        if ((status = store_point(hb, omega)) != FRICREG_OK || last)
            return status;
        rescale(hb, b);
        memcpy(b->yc, hb->qw, (nq + 1) * sizeof(double));
        if (its <= 4)
            ds = fmin(1.5 * ds, hb->ds_max);
    }
}

int fricreg_hb_continue(fricreg_hb *hb, double omega0, double omega1, size_t nq, const double q0[])
{
    if (hb == NULL)
        return FRICREG_ENULL;
    const char *fn = "continue";
    int status = fr_hb_check_start(hb, fn, omega0, nq, q0);
    if (status == FRICREG_OK && !isfinite(omega1))
        status = fr_fail(hb, FRICREG_ENONFINITE, "%s: Omega1 = %g", fn, omega1);
    if (status == FRICREG_OK && (!(omega1 > 0.0) || omega1 == omega0))
        status = fr_fail(hb, FRICREG_EINVAL, "%s: Omega1 = %g must be > 0 and differ from %g", fn,
                         omega1, omega0);
    /* the first 64 points' room before anything changes: a failure here changes nothing */
    if (status != FRICREG_OK || (status = reserve(hb, 64)) != FRICREG_OK)
        return status;
    hb->npts = 0;
    if ((status = fr_hb_solve_at(hb, fn, omega0, q0)) != FRICREG_OK)
        return status;
    struct branch b = {.ws = fabs(omega1 - omega0), .yc = hb->yp, .yp = hb->yp + nq + 1};
    b.qs = fr_hb_scale(hb, hb->qw);
    memcpy(hb->qt, hb->qw, nq * sizeof(double));
    if ((status = store_point(hb, omega0)) != FRICREG_OK)
        return status;
    for (size_t j = 0; j < nq; j++)
        b.yc[j] = hb->qw[j] / b.qs;
    b.yc[nq] = omega0 / b.ws;
    struct fr_error before = hb->err; /* a success keeps it: the halved steps' failures are not
                                         the call's */
    if ((status = follow(hb, fn, &b, omega1)) == FRICREG_OK)
        hb->err = before;
    return status;
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
