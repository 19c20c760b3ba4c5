/* SPDX-License-Identifier: GPL-3.0-or-later */
/* nma_arclength.c — a nonlinear mode's backbone by pseudo-arclength continuation
 * (fricreg_hb_nma_continue, fricreg_hb.h; H. B. Keller 1977, Krack & Gross 2019, Ch. 5, as the
 * forced response's arclength.c), so that it passes the folds of the backbone in the amplitude
 * (an internal resonance: k ω crossing another mode's frequency) where the natural-parameter
 * march in log a (nma.c) stops.
 *
 * The unknowns, scaled: z = (u, ω/ω_k, ξ/ω_k, log(a/a0)) with u the harmonics of q
 * over a u_s (u_s the largest |q|/a so far, so u is the normalized shape, O(1)) and each
 * row's mean over a0 u_s; the equations those of the extended periodic motion concept
 * (fr_hb_nma_system), (R) over a u_s and the amplitude rows over a, nondimensional; the
 * Jacobian the chain rule on fr_hb_nma_system's, its log-amplitude column from
 * ∂q/∂log a = q (the harmonics) and the amplitude rows' explicit −a. Bordered by the
 * arclength's hyperplane, Newton's method with the line search of the forced response's
 * corrector, the step control its own (arclength.h), a step rejected (halved) when the
 * corrector fails, ends beyond 4 ds, or turns the tangent by more than 20° or contracts by more
 * than 1/2 in its first steps (unless halving no longer helps: a kink of the stick/slip
 * pattern). The start at a0 is the natural-parameter march's (nma.c): cheaper where the
 * backbone is the linear mode. A fold is where the tangent's log a component changes sign; it
 * is located by that component's linear interpolation between the two points, the point there
 * corrected onto the branch. The stored points are npoints at equal arclength along the
 * branch (in z), each corrected onto the branch on the hyperplane normal to its stretch. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "hb/step_control.h"
#include "base/line_search.h"
#include "base/newton_loop.h"
#include "nma_internal.h"
#include "hb/lu.h"
#include "hb/monitor.h"
#include "base/free_all.h"

struct backbone {
    fricreg_hb *hb;
    const char *fn;
    struct fr_hb_nma *s;
    size_t nz;               /* nd + 1 */
    double us, t0, tw, zend; /* the shape's scale, log a0, log a's scale, z's at a1 */
    double a0, a1;           /* the ends, exactly there */
    /* [nz nz] the bordered matrix (LU in place), [nz] the residual, the step, the iterate */
    double *B, *F, *dz, *w;
    double *base, *tan, *tn, *zc, *zp, *anchor, *row; /* [nz] each */
    double *y, *cs, *R; /* [nz] each: the unknowns unscaled, dy/dz, the unscaled residual */
    int *piv;
    double *pts; /* the branch: per point z and the tangent's log a component */
    size_t npts, cap;
    double delta, kappa, r, bound; /* the corrector's first step and contraction; its measure */
    int converged, tiny;           /* tiny: Newton's last step within the tolerance of z */
};

static int harmonic(const struct backbone *b, size_t j)
{
    return j < b->s->nq && j % b->s->nc != 0;
}

/* The unknowns y (q, ω, ξ) at z and the column scales dy/dz into cs; returns the amplitude
 * (a0 and a1 exactly at the ends). */
static double unscale(const struct backbone *b, const double *z, double *y, double *cs)
{
    size_t nq = b->s->nq;
    double t = z[b->s->nd], a0 = b->a0;
    double a = t == 0.0 ? a0 : t == b->zend ? b->a1 : exp(b->t0 + b->tw * t);
    for (size_t j = 0; j < nq; j++) {
        cs[j] = (harmonic(b, j) ? a : a0) * b->us;
        y[j] = z[j] * cs[j];
    }
    cs[nq] = cs[nq + 1] = b->s->omega_k;
    y[nq] = z[nq] * cs[nq];
    y[nq + 1] = z[nq + 1] * cs[nq + 1];
    return a;
}

/* F (the border's equation last) and the bordered matrix B at the iterate w, its border row
 * b->row through b->anchor; the convergence measure. */
static int bordered(struct backbone *b)
{
    struct fr_hb_nma *s = b->s;
    size_t nq = s->nq, nd = s->nd, nz = b->nz;
    double *y = b->y, *cs = b->cs, *R = b->R;
    double a = unscale(b, b->w, y, cs);
    s->amplitude = s->scale = a;
    int status = fr_hb_nma_system(b->hb, b->fn, s, y, R, 1);
    if (status != FRICREG_OK)
        return status;
    double qmax = 0.0;
    b->r = 0.0;
    for (size_t j = 0; j < nd; j++) {
        double rs = j < nq ? 1.0 / (a * b->us) : 1.0 / a, dt = 0.0;
        b->F[j] = rs * R[j];
        for (size_t k = 0; k < nd; k++) {
            b->B[j * nz + k] = rs * s->A[j * nd + k] * cs[k];
            if (harmonic(b, k))
                dt += s->A[j * nd + k] * y[k];
        }
        b->B[j * nz + nd] = b->tw * (rs * dt - b->F[j] - (j == nq ? 1.0 : 0.0));
        if (j < nq) {
            b->r = fmax(b->r, fabs(b->F[j]));
            qmax = fmax(qmax, fabs(b->w[j]));
        }
    }
    double g = 0.0;
    for (size_t k = 0; k < nz; k++)
        g += b->row[k] * (b->w[k] - b->anchor[k]);
    memcpy(b->B + nd * nz, b->row, nz * sizeof(double));
    b->F[nd] = g;
    b->bound = b->hb->tol * fmax(qmax, 1e-300);
    double ra = fmax(fabs(b->F[nq]), fabs(b->F[nq + 1]));
    b->converged = b->r <= b->bound && ra <= b->hb->tol && fabs(g) <= b->hb->tol;
    return FRICREG_OK;
}

/* B factored and x solved in place: FRICREG_ESINGULAR when a pivot is below 1e-14 of B's
 * largest entry (nma_solve.c's rule). */
static int solve(struct backbone *b, double *x)
{
    size_t nz = b->nz;
    double amax = 0.0;
    for (size_t k = 0; k < nz * nz; k++)
        amax = fmax(amax, fabs(b->B[k]));
    fr_hb_lu_factor(b->B, nz, b->piv);
    for (size_t k = 0; k < nz; k++) {
        double p = fabs(b->B[k * nz + k]);
        if (!(p > 1e-14 * amax) || !isfinite(p))
            return fr_fail(b->hb, FRICREG_ESINGULAR,
                           "%s: the backbone's bordered matrix is singular at amplitude %g", b->fn,
                           b->s->amplitude);
    }
    fr_hb_lu_solve_factored(b->B, nz, b->piv, x);
    return FRICREG_OK;
}

/* The unit tangent into t at the iterate (B evaluated, its border row the last), oriented
 * along the border. */
static int tangent(struct backbone *b, double *t)
{
    memset(t, 0, b->nz * sizeof(double));
    t[b->nz - 1] = 1.0;
    int status = solve(b, t);
    if (status != FRICREG_OK)
        return status;
    double n = sqrt(fr_hb_dot(t, t, b->nz));
    for (size_t j = 0; j < b->nz; j++)
        t[j] /= n;
    return FRICREG_OK;
}

/* ---- The corrector: Newton's method bordered by row^T (z − anchor) = 0 (corrector.c's). ---- */

struct backbone_loop {
    struct backbone *b;
    struct fr_line_search ls;
    double prev;
    int it;
};

static int bb_converged(void *user)
{
    return ((struct backbone_loop *)user)->b->converged;
}

static int bb_progress(void *user, double rinf)
{
    struct backbone *b = ((struct backbone_loop *)user)->b;
    (void)rinf;
    return fr_hb_tick(b->hb, b->fn, b->s->amplitude, b->r / b->bound);
}

static int bb_direction(void *user)
{
    struct backbone_loop *l = user;
    struct backbone *b = l->b;
    for (size_t j = 0; j < b->nz; j++)
        b->dz[j] = -b->F[j];
    int status = solve(b, b->dz);
    if (status != FRICREG_OK)
        return status;
    double step = sqrt(fr_hb_dot(b->dz, b->dz, b->nz)), qs = 0.0, dq = 0.0, tol = b->hb->tol;
    size_t nq = b->s->nq, nd = b->s->nd;
    for (size_t j = 0; j < nq; j++) {
        qs = fmax(qs, fabs(b->w[j]));
        dq = fmax(dq, fabs(b->dz[j]));
    }
    b->tiny = dq <= tol * qs && fabs(b->dz[nq]) <= tol * fabs(b->w[nq]) &&
              fabs(b->dz[nq + 1]) <= tol * fabs(b->w[nq]) && fabs(b->dz[nd]) <= tol;
    if (l->it == 0)
        b->delta = step;
    else if (l->it == 1 && b->delta > 0.0)
        b->kappa = step / b->delta;
    l->it++;
    return FRICREG_OK;
}

static int bb_trial(void *user, double lambda, int *accept)
{
    struct backbone_loop *l = user;
    struct backbone *b = l->b;
    for (size_t j = 0; j < b->nz; j++)
        b->w[j] = b->base[j] + lambda * b->dz[j];
    int status = bordered(b);
    *accept = status == FRICREG_OK &&
              (b->converged ||
               fr_armijo_decrease(&l->ls, l->prev, sqrt(fr_hb_dot(b->F, b->F, b->nz)), lambda));
    return status;
}

/* As corrector.c's: where no trial decreases |F|, on from the shortest; converged there if
 * Newton's own step was within the tolerance of z (|F| at the rounding floor of the model's
 * scale, as fr_hb_nma_newton's). */
static int bb_search(void *user, double *phi, double *rinf, int *accepted)
{
    struct backbone_loop *l = user;
    struct backbone *b = l->b;
    (void)phi;
    (void)rinf;
    memcpy(b->base, b->w, b->nz * sizeof(double));
    l->prev = sqrt(fr_hb_dot(b->F, b->F, b->nz));
    int found, status = fr_line_search(&l->ls, 1.0, bb_trial, l, &found);
    *accepted = 1;
    if (status == FRICREG_OK && !found && b->tiny)
        b->converged = 1;
    return status;
}

/* From start onto the branch, on the hyperplane row^T (z − anchor) = 0, into w; *its its
 * iterations. On success B holds the bordered matrix at w, unfactored. */
static int corrector(struct backbone *b, const double *start, const double *anchor,
                     const double *row, int *its)
{
    memcpy(b->w, start, b->nz * sizeof(double));
    if (anchor != b->anchor)
        memcpy(b->anchor, anchor, b->nz * sizeof(double));
    if (row != b->row)
        memcpy(b->row, row, b->nz * sizeof(double));
    b->delta = b->kappa = 0.0;
    int status = bordered(b);
    if (status != FRICREG_OK)
        return status;
    struct backbone_loop l = {b, {FR_ARMIJO, FR_HB_HALVINGS, NULL}, 0.0, 0};
    struct fr_newton_loop nl = {1.0,  b->hb->max_iter, 1,           &l, bb_direction, bb_search,
                                NULL, bb_progress,     bb_converged};
    double phi = 0.0, rinf = 0.0;
    int iters = 0;
    if ((status = fr_newton_loop_run(&nl, &phi, &rinf, &iters)) != FRICREG_OK)
        return status;
    if (iters == 0 || !b->converged)
        return fr_fail(b->hb, FRICREG_EWORK,
                       "%s: the corrector did not converge in %d iterations at amplitude %g", b->fn,
                       iters, b->s->amplitude);
    *its = iters;
    return FRICREG_OK;
}

/* ---- The continuation: steps along the tangent, the points, the folds, the output. ---- */

static void keep_point(struct backbone *b, const double *z, double tau)
{
    double *p = b->pts + b->npts * (b->nz + 1);
    memcpy(p, z, b->nz * sizeof(double));
    p[b->nz] = tau;
    b->npts++;
}

/* One step from zc along tan by ds: 0 accepted (w the point, tn its tangent), -1 rejected, or
 * a status that ends the continuation (no memory, stopped). *sev as arclength.c's attempt. */
static int attempt(struct backbone *b, double ds, int *its, double *alpha, double *sev,
                   double sev_before, int *kink)
{
    size_t nz = b->nz;
    for (size_t j = 0; j < nz; j++)
        b->zp[j] = b->zc[j] + ds * b->tan[j];
    *alpha = *sev = 0.0;
    *kink = 0;
    int status = corrector(b, b->zp, b->zp, b->tan, its);
    if (status == FRICREG_OK)
        status = tangent(b, b->tn);
    if (status == FRICREG_ENOMEM || b->hb->stopped)
        return status;
    if (status != FRICREG_OK)
        return -1;
    *alpha = acos(fmax(-1.0, fmin(1.0, fr_hb_dot(b->tn, b->tan, nz))));
    if (fr_hb_dist(b->w, b->zc, nz) > JUMP * ds) {
        fr_fail(b->hb, FRICREG_EWORK, "%s: the corrector ended beyond %g ds", b->fn, JUMP);
        return -1;
    }
    *sev = fmax(*alpha / ALPHA_MAX, b->kappa / KAPPA_MAX);
    if (*sev <= 1.0)
        return 0;
    if (sev_before > 0.0 && *sev >= 0.75 * sev_before && *alpha < KINK_MAX) {
        *kink = 1;
        return 0;
    }
    fr_fail(b->hb, FRICREG_EWORK,
            "%s: the tangent turned by %.3g degrees and the corrector contracted by %.3g", b->fn,
            *alpha * 57.29577951308232, b->kappa);
    return -1;
}

/* The last point, at a1 exactly (z's log a component 1), from the predictor zp. */
static int final_point(struct backbone *b)
{
    size_t nd = b->s->nd;
    int its;
    memcpy(b->anchor, b->zp, b->nz * sizeof(double));
    b->anchor[nd] = b->zend;
    memset(b->row, 0, b->nz * sizeof(double));
    b->row[nd] = 1.0;
    int status = corrector(b, b->anchor, b->anchor, b->row, &its);
    if (status == FRICREG_OK)
        status = tangent(b, b->tn);
    if (status == FRICREG_OK) /* the border is linear: within rounding of a1, now a1 exactly */
        b->w[nd] = b->zend;
    return status;
}

/* One accepted step from zc into w (*last: the point at a1), or a status that ends it. */
static int step(struct backbone *b, double *ds, int *last)
{
    size_t nz = b->nz, nd = b->s->nd;
    double sev_before = 0.0;
    for (;;) {
        int its = 0, kink = 0;
        double alpha = 0.0, sev = 0.0;
        int r;
        if (b->zc[nd] + *ds * b->tan[nd] >= b->zend) {
            for (size_t j = 0; j < nz; j++)
                b->zp[j] = b->zc[j] + *ds * b->tan[j];
            r = final_point(b);
            if ((*last = r == FRICREG_OK))
                return r;
            if (r == FRICREG_ENOMEM || b->hb->stopped)
                return r;
        } else if ((r = attempt(b, *ds, &its, &alpha, &sev, sev_before, &kink)) >= 0) {
            if (r > 0)
                return r;
            *ds = fr_hb_next_step(b->hb, *ds, b->kappa, b->delta, kink ? 0.0 : alpha, its);
            return 0;
        }
        sev_before = sev;
        if (sev > 0.0 && alpha < KINK_MAX && 0.5 * *ds < b->hb->ds_min)
            return 0; /* a converged corrector near the branch: accepted, as arclength.c */
        if ((*ds *= 0.5) < b->hb->ds_min) {
            char why[256];
            memcpy(why, b->hb->err.msg, sizeof why);
            why[sizeof why - 1] = '\0';
            return fr_fail(b->hb, FRICREG_EINTEGRATOR,
                           "%s: the step fell below ds_min = %g at amplitude %g (last failure: "
                           "%s)",
                           b->fn, b->hb->ds_min, exp(b->t0 + b->tw * b->zc[nd]), why);
        }
    }
}

/* The shape's scale follows the branch up, as the forced response's (arclength.c): u_s the
 * largest |q|/a so far, so that a shape that grows along the branch (a joint near a node of
 * the stuck mode, free once it slips) does not stretch the arclength; the new point w, its
 * tangent tn and the points kept converted to the new scale. */
static void rescale(struct backbone *b)
{
    size_t nq = b->s->nq, st = b->nz + 1;
    double top = 0.0;
    for (size_t j = 0; j < nq; j++)
        top = fmax(top, fabs(b->w[j]));
    if (!(top > 1.0))
        return;
    for (size_t j = 0; j < nq; j++) {
        b->w[j] /= top;
        b->tn[j] /= top;
        for (size_t i = 0; i < b->npts; i++)
            b->pts[i * st + j] /= top;
    }
    double n = sqrt(fr_hb_dot(b->tn, b->tn, b->nz));
    for (size_t j = 0; j < b->nz; j++)
        b->tn[j] /= n;
    b->us *= top;
}

static int follow(struct backbone *b)
{
    size_t nz = b->nz, nd = b->s->nd;
    memcpy(b->w, b->zc, nz * sizeof(double));
    memcpy(b->anchor, b->zc, nz * sizeof(double));
    memset(b->row, 0, nz * sizeof(double));
    b->row[nd] = 1.0; /* the first tangent towards a1 */
    int first = bordered(b);
    if (first == FRICREG_OK)
        first = tangent(b, b->tan);
    if (first != FRICREG_OK)
        return first;
    keep_point(b, b->zc, b->tan[nd]);
    double ds = b->hb->ds0;
    for (;;) {
        if (b->npts >= b->cap)
            return fr_fail(b->hb, FRICREG_EWORK, "%s: %zu points of the branch before a1", b->fn,
                           b->npts);
        int last = 0, status = step(b, &ds, &last);
        if (status != FRICREG_OK)
            return status;
        rescale(b);
        keep_point(b, b->w, b->tn[nd]);
        if (last)
            return FRICREG_OK;
        memcpy(b->zc, b->w, nz * sizeof(double));
        memcpy(b->tan, b->tn, nz * sizeof(double));
    }
}

/* A point z stored as the backbone's i-th: a, ω, ξ, q. */
static void store_point(struct backbone *b, const double *z, double *p)
{
    struct fr_hb_nma *s = b->s;
    double *y = b->y;
    p[0] = unscale(b, z, y, b->cs);
    p[1] = y[s->nq];
    p[2] = y[s->nq + 1];
    memcpy(p + 3, y, s->nq * sizeof(double));
}

/* The branch's point between its points i and i + 1 at the fraction th, corrected onto the
 * branch normal to that stretch into w (else, if the corrector fails, the nearer point). */
static void between(struct backbone *b, size_t i, double th)
{
    size_t nz = b->nz, st = nz + 1;
    const double *p0 = b->pts + i * st, *p1 = p0 + st;
    double h = fr_hb_dist(p0, p1, nz);
    for (size_t j = 0; j < nz; j++) {
        b->zp[j] = p0[j] + th * (p1[j] - p0[j]);
        b->tn[j] = (p1[j] - p0[j]) / h;
    }
    int its;
    if (h > 0.0 && !b->hb->stopped && corrector(b, b->zp, b->zp, b->tn, &its) == FRICREG_OK)
        return;
    memcpy(b->w, th < 0.5 ? p0 : p1, nz * sizeof(double));
}

/* The folds: where the tangent's log a component changes sign between two points, located
 * by its linear interpolation there; each one's arclength along the chords (in z) into f[3],
 * made a place among the stored points by resample. */
static int find_folds(struct backbone *b)
{
    struct fr_hb_nma *s = b->s;
    size_t st = b->nz + 1;
    double along = 0.0;
    s->nfolds = 0;
    if (b->npts < 2)
        return FRICREG_OK;
    if ((s->folds = malloc(4 * (b->npts - 1) * sizeof(double))) == NULL)
        return fr_fail(b->hb, FRICREG_ENOMEM, "%s: no memory for the folds", b->fn);
    for (size_t i = 0; i + 1 < b->npts; i++) {
        const double *p0 = b->pts + i * st, *p1 = p0 + st;
        double t0 = p0[b->nz], t1 = p1[b->nz], h = fr_hb_dist(p0, p1, b->nz);
        if ((t0 > 0.0 && t1 < 0.0) || (t0 < 0.0 && t1 > 0.0)) {
            double *f = s->folds + 4 * s->nfolds++, *y = b->y, th = t0 / (t0 - t1);
            between(b, i, th);
            f[0] = unscale(b, b->w, y, b->cs);
            f[1] = y[s->nq];
            f[2] = y[s->nq + 1];
            f[3] = along + th * h;
        }
        along += h;
    }
    return FRICREG_OK;
}

/* n points at equal arclength (in z) along the branch, the ends its own. */
static int resample(struct backbone *b, size_t n)
{
    struct fr_hb_nma *s = b->s;
    size_t st = b->nz + 1, k = 0;
    double *len = malloc(b->npts * sizeof(double));
    if (len == NULL)
        return fr_fail(b->hb, FRICREG_ENOMEM, "%s: no memory for the branch's lengths", b->fn);
    len[0] = 0.0;
    for (size_t i = 1; i < b->npts; i++)
        len[i] = len[i - 1] + fr_hb_dist(b->pts + (i - 1) * st, b->pts + i * st, b->nz);
    s->npts = 0;
    for (size_t o = 0; o < n; o++) {
        double at = n > 1 ? len[b->npts - 1] * (double)o / (double)(n - 1) : 0.0;
        double *p = s->pts + s->npts++ * s->stride;
        if (o == 0 || o + 1 == n || b->npts < 2) {
            store_point(b, b->pts + (o == 0 ? 0 : b->npts - 1) * st, p);
            continue;
        }
        while (k + 2 < b->npts && len[k + 1] < at)
            k++;
        double h = len[k + 1] - len[k];
        between(b, k, h > 0.0 ? (at - len[k]) / h : 0.0);
        store_point(b, b->w, p);
    }
    double total = len[b->npts - 1]; /* the stored points are at equal arclength: each fold's */
    for (size_t f = 0; f < s->nfolds; f++) /* place among them, index plus fraction */
        s->folds[4 * f + 3] = n > 1 && total > 0.0 ? s->folds[4 * f + 3] / total * (double)(n - 1)
                                                   : 0.0;
    free(len);
    return FRICREG_OK;
}

static void bb_free(struct backbone *b)
{
    FR_FREE_ALL(b->B, b->piv, b->pts);
}

static int bb_alloc(struct backbone *b)
{
    size_t nz = b->nz;
    b->B = malloc((nz * nz + 13 * nz) * sizeof(double));
    b->piv = malloc(nz * sizeof *b->piv);
    b->pts = malloc(b->cap * (nz + 1) * sizeof(double));
    if (b->B == NULL || b->piv == NULL || b->pts == NULL) {
        bb_free(b);
        return FRICREG_ENOMEM;
    }
    double *v = b->B + nz * nz;
    double **vecs[13] = {&b->F,  &b->dz,     &b->w,   &b->base, &b->tan, &b->tn, &b->zc,
                         &b->zp, &b->anchor, &b->row, &b->y,    &b->cs,  &b->R};
    for (int k = 0; k < 13; k++)
        *vecs[k] = v + (size_t)k * nz;
    return FRICREG_OK;
}

/* The start's point (nma->yc at a0) scaled: the shape's scale from its harmonics. */
static void start_point(struct backbone *b, double a0)
{
    struct fr_hb_nma *s = b->s;
    double qmax = 0.0;
    for (size_t j = 0; j < s->nq; j++)
        if (harmonic(b, j))
            qmax = fmax(qmax, fabs(s->yc[j]));
    b->us = qmax > 0.0 ? qmax / a0 : 1.0;
    for (size_t j = 0; j < s->nq; j++)
        b->zc[j] = s->yc[j] / (a0 * b->us);
    b->zc[s->nq] = s->yc[s->nq] / s->omega_k;
    b->zc[s->nq + 1] = s->yc[s->nq + 1] / s->omega_k;
    b->zc[s->nd] = 0.0;
}

/* The backbone from a0 to a1 (the march to a0 first), npoints points stored along it at equal
 * arclength, its folds in nma->folds; on failure the branch reached. */
static int arclength(fricreg_hb *hb, const char *fn, struct fr_hb_nma *nma, double a0, double a1,
                     size_t npoints)
{
    struct backbone b = {.hb = hb,
                         .fn = fn,
                         .s = nma,
                         .nz = nma->nd + 1,
                         .t0 = log(a0),
                         .tw = 1.0,
                         .zend = log(a1 / a0),
                         .a0 = a0,
                         .a1 = a1,
                         .cap = hb->max_points};
    if (bb_alloc(&b) != FRICREG_OK)
        return fr_fail(hb, FRICREG_ENOMEM, "%s: no memory for %zu points of the branch", fn, b.cap);
    int status = fr_hb_nma_march_to(hb, fn, nma, a0);
    if (status == FRICREG_OK) {
        start_point(&b, a0);
        status = follow(&b);
    }
    /* the points reached kept, with the failure's record */
    struct fr_error err = hb->err;
    int post = FRICREG_OK;
    if (b.npts > 0) { /* once stopped, no corrector runs: the nearer points stand in */
        post = find_folds(&b);
        if (post == FRICREG_OK)
            post = resample(&b, status == FRICREG_OK || b.npts > npoints ? npoints : b.npts);
    }
    bb_free(&b);
    if (status != FRICREG_OK)
        hb->err = err;
    return status != FRICREG_OK ? status : post;
}

int fricreg_hb_nma_continue(fricreg_hb *hb, size_t mode, int damping, double a0, double a1,
                            size_t npoints)
{
    return fr_hb_nma_run(hb, "nma_continue", mode, damping, a0, a1, npoints, arclength);
}
