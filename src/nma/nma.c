/* SPDX-License-Identifier: GPL-3.0-or-later */
/* nma.c — nonlinear modes (fricreg_hb_nma, fricreg_hb.h): the backbone of mode k by natural-
 * parameter continuation in the modal amplitude a, on a logarithmic grid from a0 to a1, from the
 * linear mode of the structure with its elements stuck (nma_linear.c): below the smallest
 * amplitude at which an element slips (or opens) the mode is that linear mode exactly, so the
 * march starts there (or at a0 if smaller) and each step's predictor is the secant of the last
 * two solutions in (q/a, ω, ξ) against log a, each row's mean in itself (the first step's the
 * last solution's shape). A
 * step whose corrector fails is halved, down to 1/1024 of the grid's step. The backbone of a
 * friction-damped mode is monotone in a (no turning point: ω falls and ζ changes smoothly as
 * the elements slip more), which is what a natural parameter needs; a mode that folds in a (an
 * internal resonance) stops the march there. The grid's points are stored; the substeps not. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "nma_internal.h"
#include "hb/monitor.h"
#include "hb/busy.h"
#include "hb/recover.h"
#include "base/free_all.h"

#define MAX_HALVINGS 10

static void nma_free(struct fr_hb_nma *nma)
{
    if (nma == NULL)
        return;
    FR_FREE_ALL(nma->phi, nma->dGx, nma->A, nma->piv, nma->pts, nma->folds, nma->special,
                nma->modes, nma);
}

/* The driver's release of its nonlinear modes (fricreg_hb_free). */
static void nma_release(fricreg_hb *hb)
{
    nma_free(hb->nma);
    hb->nma = NULL;
}

/* The state for the driver's sizes and npoints points, all or nothing. */
static struct fr_hb_nma *alloc_state(const fricreg_hb *hb, size_t npoints)
{
    size_t n = hb->n, m = hb->m, H1 = (size_t)hb->H + 1, nq = hb->nq, nd = nq + 2;
    struct fr_hb_nma *s = calloc(1, sizeof *s);
    if (s == NULL)
        return NULL;
    *s = (struct fr_hb_nma){
        .n = n, .nq = nq, .nd = nd, .nc = hb->nc, .cap = npoints, .stride = nq + 3};
    s->phi = calloc(4 * n, sizeof(double));
    s->dGx = malloc((2 * H1 * m * m + 2 * H1 * m) * sizeof(double));
    s->A = malloc((nd * nd + 10 * nd) * sizeof(double));
    s->piv = malloc(nd * sizeof *s->piv);
    s->pts = malloc(npoints * s->stride * sizeof(double));
    if (!s->phi || !s->dGx || !s->A || !s->piv || !s->pts) {
        nma_free(s);
        return NULL;
    }
    s->w = s->phi + n;
    s->zero = s->w + n;
    s->lambda = s->zero + n;
    s->dgx = s->dGx + 2 * H1 * m * m;
    double *v = s->A + nd * nd;
    double **vecs[8] = {&s->y, &s->yt, &s->R, &s->Rt, &s->dy, &s->col, &s->yc, &s->yo};
    for (int k = 0; k < 8; k++)
        *vecs[k] = v + (size_t)k * nd;
    return s;
}

static int check_args(fricreg_hb *hb, const char *fn, size_t mode, int damping, double a0,
                      double a1, size_t npoints)
{
    if (!hb->have_elements)
        return fr_fail(hb, FRICREG_EINVAL, "%s: no elements (fricreg_hb_set_elements)", fn);
    if (mode >= hb->n)
        return fr_fail(hb, FRICREG_EINVAL, "%s: mode = %zu, the structure has %zu modes (from 0)",
                       fn, mode, hb->n);
    if (damping != FRICREG_HB_NMA_DAMPING_MATRIX && damping != FRICREG_HB_NMA_DAMPING_MODAL)
        return fr_fail(hb, FRICREG_EINVAL,
                       "%s: damping = %d is not one of enum "
                       "fricreg_hb_nma_damping",
                       fn, damping);
    if (hb->nma_targets != NULL) /* fricreg_hb_nma_at: its amplitudes checked there */
        return FRICREG_OK;
    if (!isfinite(a0) || !isfinite(a1))
        return fr_fail(hb, FRICREG_ENONFINITE, "%s: a0 = %g, a1 = %g", fn, a0, a1);
    if (!(a0 > 0.0 && a1 > a0))
        return fr_fail(hb, FRICREG_EINVAL, "%s: need 0 < a0 = %g < a1 = %g", fn, a0, a1);
    if (npoints < 2 || npoints > hb->max_points)
        return fr_fail(hb, FRICREG_EINVAL, "%s: npoints = %zu must be in [2, max_points = %zu]", fn,
                       npoints, hb->max_points);
    return FRICREG_OK;
}

/* The linear mode at amplitude a as the iterate: q's cosine coefficient a J φ, ω_k, ξ_k. */
static void linear_guess(const fricreg_hb *hb, struct fr_hb_nma *s, double a)
{
    size_t n = hb->n, nc = hb->nc;
    memset(s->y, 0, s->nd * sizeof(double));
    for (size_t r = 0; r < hb->m; r++) {
        double q = 0.0;
        for (size_t k = 0; k < n; k++)
            q += hb->J[r * n + k] * s->phi[k];
        s->y[r * nc + 1] = a * q;
    }
    s->y[s->nq] = s->omega_k;
    s->y[s->nq + 1] = s->xi_k;
}

/* The predictor at log-amplitude t from the last solution yc (at tc) and the one before, yo
 * (at to; have_prev), in (q/a, ω, ξ): the harmonics scale with a, but each row's mean does
 * not (a preload's static deflection is there at every amplitude), so it is extrapolated as
 * itself, as ω and ξ are. */
static void predict(struct fr_hb_nma *s, double t, double tc, double to, int have_prev)
{
    size_t nq = s->nq;
    double r = have_prev ? (t - tc) / (tc - to) : 0.0, ac = exp(tc), ao = exp(to), a = exp(t);
    for (size_t j = 0; j < s->nd; j++) {
        int scaled = j < nq && j % s->nc != 0;
        double uc = scaled ? s->yc[j] / ac : s->yc[j], uo = scaled ? s->yo[j] / ao : s->yo[j];
        double u = have_prev ? uc + r * (uc - uo) : uc;
        s->y[j] = scaled ? a * u : u;
    }
}

struct march {
    double tc, to; /* log-amplitudes of yc and yo */
    int have_prev;
};

/* From the last solution to log-amplitude t, in steps halved while the corrector fails. A step
 * that would leave t a rounding short of it ends at t: a step of 1e-17 after it would make
 * the next predictor's secant (t − tc) / (tc − to) overflow, and its corrector wander to
 * another mode (60 dofs, a grid scaled by 1 − 2e-5: mode 2's backbone left for ω = 0.92). */
static int advance(fricreg_hb *hb, const char *fn, struct fr_hb_nma *s, struct march *mc, double t)
{
    double h = t - mc->tc, hmin = h / (1 << MAX_HALVINGS);
    while (mc->tc < t) {
        double tn = mc->tc + h;
        if (t - tn <= 1e-9 * h) /* the last step ends at t: tc + (t − tc) may round below it */
            tn = t;
        predict(s, tn, mc->tc, mc->to, mc->have_prev);
        int status = fr_hb_nma_newton(hb, fn, s, exp(tn));
        if (status == FRICREG_ENOMEM || status == FRICREG_ENONFINITE || hb->stopped)
            return status;
        if (status != FRICREG_OK) {
            if ((h *= 0.5) < hmin)
                return status;
            continue;
        }
        memcpy(s->yo, s->yc, s->nd * sizeof(double));
        memcpy(s->yc, s->y, s->nd * sizeof(double));
        mc->to = mc->tc;
        mc->tc = tn;
        mc->have_prev = 1;
    }
    return FRICREG_OK;
}

static void store(struct fr_hb_nma *s, double a)
{
    double *p = s->pts + s->npts * s->stride;
    p[0] = a;
    p[1] = s->yc[s->nq];
    p[2] = s->yc[s->nq + 1];
    memcpy(p + 3, s->yc, s->nq * sizeof(double));
    s->npts++;
}

/* The march's start: the linear mode below the first slip, then on to a0 (yc the solution). */
static int march_start(fricreg_hb *hb, const char *fn, struct fr_hb_nma *s, struct march *mc,
                       double a0)
{
    double a_start = fmin(a0, 0.5 * s->a_stick);
    linear_guess(hb, s, a_start);
    int status = fr_hb_nma_newton(hb, fn, s, a_start);
    if (status != FRICREG_OK)
        return status;
    memcpy(s->yc, s->y, s->nd * sizeof(double));
    *mc = (struct march){.tc = log(a_start)};
    return log(a0) > mc->tc ? advance(hb, fn, s, mc, log(a0)) : FRICREG_OK;
}

int fr_hb_nma_march_to(fricreg_hb *hb, const char *fn, struct fr_hb_nma *s, double a0)
{
    struct march mc;
    return march_start(hb, fn, s, &mc, a0);
}

/* The march: the linear mode below the first slip, then each grid amplitude in turn. */
static int backbone(fricreg_hb *hb, const char *fn, struct fr_hb_nma *s, double a0, double a1,
                    size_t npoints)
{
    struct march mc;
    int status = march_start(hb, fn, s, &mc, a0);
    if (status != FRICREG_OK)
        return status;
    for (size_t i = 0; i < npoints; i++) {
        double t = i + 1 == npoints ? log(a1)
                                    : log(a0) + (log(a1) - log(a0)) * (double)i / (npoints - 1);
        if (t > mc.tc && (status = advance(hb, fn, s, &mc, t)) != FRICREG_OK)
            return status;
        store(s, exp(t));
    }
    return FRICREG_OK;
}

int fr_hb_nma_run(fricreg_hb *hb, const char *fn, size_t mode, int damping, double a0, double a1,
                  size_t npoints, fr_hb_nma_backbone body)
{
    if (hb == NULL || hb->busy)
        return fr_hb_refuse(hb, fn);
    int status = check_args(hb, fn, mode, damping, a0, a1, npoints);
    if (status != FRICREG_OK)
        return status;
    struct fr_hb_nma *s = alloc_state(hb, npoints);
    if (s == NULL)
        return fr_fail(hb, FRICREG_ENOMEM, "%s: no memory for %zu points", fn, npoints);
    nma_free(hb->nma);
    hb->nma = s;
    hb->release[FR_HB_PART_NMA] = nma_release;
    s->model_serial = hb->model_serial;
    s->modal = damping == FRICREG_HB_NMA_DAMPING_MODAL;
    s->mode = mode;
    s->targets = hb->nma_targets;
    struct fr_error before = hb->err; /* a success keeps it: halved steps' failures are not
                                         the call's */
    if ((status = fr_hb_nma_linear(hb, fn, mode, s)) != FRICREG_OK)
        return status;
    fr_hb_nma_enter(hb, s);
    fr_hb_begin(hb, 0);
    status = fr_hb_end(hb, body(hb, fn, s, a0, a1, npoints));
    fr_hb_nma_leave(hb, s);
    if (fr_hb_nma_find_special(s) != FRICREG_OK && status == FRICREG_OK) /* points reached */
        status = fr_fail(hb, FRICREG_ENOMEM, "%s: no memory for the backbone's special points", fn);
    if (status == FRICREG_OK)
        hb->err = before;
    return status;
}

int fricreg_hb_nma(fricreg_hb *hb, size_t mode, int damping, double a0, double a1, size_t npoints)
{
    return fr_hb_nma_run(hb, "nma", mode, damping, a0, a1, npoints, backbone);
}

/* The march through the caller's amplitudes s->targets[npoints] (fricreg_hb_nma_at), each
 * stored at exp(log a), as the grid's points are. */
static int at_targets(fricreg_hb *hb, const char *fn, struct fr_hb_nma *s, double a0, double a1,
                      size_t npoints)
{
    (void)a1;
    struct march mc;
    int status = march_start(hb, fn, s, &mc, a0);
    for (size_t i = 0; status == FRICREG_OK && i < npoints; i++) {
        double t = log(s->targets[i]);
        if (t > mc.tc)
            status = advance(hb, fn, s, &mc, t);
        if (status == FRICREG_OK)
            store(s, exp(t));
    }
    return status;
}

int fricreg_hb_nma_at(fricreg_hb *hb, size_t mode, int damping, size_t n, const double amplitude[])
{
    static const char fn[] = "nma_at";
    if (hb == NULL || hb->busy)
        return fr_hb_refuse(hb, fn);
    if (amplitude == NULL)
        return fr_fail(hb, FRICREG_ENULL, "%s: amplitude is NULL", fn);
    if (n == 0 || n > hb->max_points)
        return fr_fail(hb, FRICREG_EINVAL, "%s: n = %zu must be in [1, max_points = %zu]", fn, n,
                       hb->max_points);
    for (size_t i = 0; i < n; i++) {
        if (!isfinite(amplitude[i]))
            return fr_fail(hb, FRICREG_ENONFINITE, "%s: amplitude[%zu] is not finite", fn, i);
        if (!(amplitude[i] > (i ? amplitude[i - 1] : 0.0)))
            return fr_fail(hb, FRICREG_EINVAL,
                           "%s: amplitude[%zu] = %g: the amplitudes must be > 0 and increase", fn,
                           i, amplitude[i]);
    }
    hb->nma_targets = amplitude;
    int status = fr_hb_nma_run(hb, fn, mode, damping, amplitude[0], amplitude[n - 1], n,
                               at_targets);
    hb->nma_targets = NULL;
    if (hb->nma != NULL)
        hb->nma->targets = NULL; /* the caller's array is not kept */
    return status;
}

size_t fricreg_hb_nma_points(const fricreg_hb *hb)
{
    return hb && hb->nma ? hb->nma->npts : 0;
}

int fr_hb_nma_point_args(fricreg_hb *hb, const char *fn, const double *amplitude,
                         const double *omega, const double *zeta, size_t i, size_t n,
                         const char *what)
{
    if (amplitude == NULL || omega == NULL || zeta == NULL)
        return fr_fail(hb, FRICREG_ENULL, "%s: %s is NULL", fn,
                       amplitude == NULL ? "amplitude"
                       : omega == NULL   ? "omega"
                                         : "zeta");
    if (i >= n)
        return fr_fail(hb, FRICREG_EINVAL, "%s: i = %zu, %zu %s stored", fn, i, n, what);
    return FRICREG_OK;
}

int fricreg_hb_nma_point(fricreg_hb *hb, size_t i, double *amplitude, double *omega, double *zeta,
                         size_t ndof, size_t nc, double x[])
{
    static const char fn[] = "nma_point";
    if (hb == NULL)
        return FRICREG_ENULL;
    int status = fr_hb_nma_point_args(hb, fn, amplitude, omega, zeta, i, fricreg_hb_nma_points(hb),
                                      "points");
    if (status != FRICREG_OK)
        return status;
    struct fr_hb_nma *s = hb->nma;
    if (x != NULL && (ndof != hb->n || nc != hb->nc))
        return fr_fail(hb, FRICREG_ESIZE,
                       "%s: ndof = %zu, nc = %zu, the driver has %zu and 2H + 1 = %zu", fn, ndof,
                       nc, hb->n, hb->nc);
    if (x != NULL && hb->busy) /* the evaluation would move the solve's factors */
        return fr_hb_refuse(hb, fn);
    if (x != NULL && (!fr_hb_backbone_holds(hb) || s->nq != hb->nq))
        return fr_fail(hb, FRICREG_EINVAL, "%s: the model changed since fricreg_hb_nma", fn);
    const double *p = s->pts + i * s->stride;
    if (x != NULL) {
        memcpy(s->y, p + 3, s->nq * sizeof(double));
        s->y[s->nq] = p[1];
        s->y[s->nq + 1] = p[2];
        fr_hb_nma_enter(hb, s);
        status = fr_hb_nma_evaluate(hb, fn, s, s->y, s->R);
        if (status == FRICREG_OK)
            fr_hb_recover(hb, x);
        fr_hb_nma_leave(hb, s);
    }
    if (status == FRICREG_OK) {
        *amplitude = p[0];
        *omega = p[1];
        *zeta = p[2] / (2.0 * p[1]);
    }
    return status;
}
