/* SPDX-License-Identifier: GPL-3.0-or-later */
/* hb_levels.c — the HB model's backbone at the measured levels (hb_levels.h): the driver's
 * backbone (EPMC, fricreg_hb_nma_at) through the levels' modal amplitudes and its exact
 * sensitivities (fricreg_hb_nma_point_sensitivities), carried to the measured amplitude by the
 * implicit function theorem.
 *
 * A level measures g(a, p) = S(a, p) omega(a, p)^kind = A, S the sensor's amplitude: |s| a (a
 * mode shape value s, fricreg_fit_set_sensor) or |X_1| of a dof. Its modal amplitude a solves
 * that equation by Newton's method on log a, every level's at once (one march through all their
 * amplitudes an iteration; each level's equation is scalar, so the step is
 * -(log g - log A)/(d log g/d log a), within a factor e), from the linear mode's ratio
 * a = A/(S/a omega^kind) of a probe march far below any slip, or from the last evaluation's a.
 * A displacement at the modal sensor needs no iteration: a = A/|s|. Then, with
 * G_a = d log g/da and G_p = d log g/dp at the point,
 *
 *     da/dp = -G_p/G_a,    d omega/dp = omega_p + omega_a da/dp,    dzeta/dp likewise,
 *
 * G_a <= 0 a fold of the measured amplitude in a: there the level is out of reach. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/fr_math.h"
#include "hb_levels.h"

#define NEWTON_TOL 1e-10 /* |log g - log A|: each level's amplitude to 1e-10 relative */
#define NEWTON_MAX 40    /* iterations (marches) of the levels' Newton */
#define MAX_LOG_STEP 1.0 /* a Newton step moves log a by at most 1 */
#define PROBE 1e-9       /* the linear probe's modal amplitude over the smallest level's */
#define SAME 1e-12       /* modal amplitudes this close (relative) share one point */
#define MAX_RATIO 1.2    /* points between levels farther apart: the march's grid step */
#define FINE_RATIO 1.05  /* the same for a march again after one that stopped */
#define MAX_FILL 256     /* such points in one march at most */
#define JUMP_NEAR 1e-3   /* Newton's error below this: converging, the next one smaller */
#define JUMP_RISE 10.0   /* a rise by this factor there: the march took another branch */

struct work {
    size_t n, u, np1, cap, nl; /* levels, points, the parameters and a, points at most, the
                                  levels' points */
    double ratio;              /* the points' largest step: MAX_RATIO or FINE_RATIO */
    double *a;                 /* [n] each level's modal amplitude */
    double *ua;                /* [cap] the points' amplitudes, increasing (u of them) */
    double *w, *z, *s;         /* [cap] each point's omega, zeta and sensor amplitude S */
    double *dw, *dz, *ds;      /* [cap np1] their derivatives in the parameters, then a */
    double *x, *damp;          /* [ndof nc], [np1 ndof] with a dof */
    size_t *order, *pt, *lp;   /* [n] the levels by a; each level's point; the levels' points */
};

static int alloc_work(const fricreg_fit *fit, size_t n, struct work *wk)
{
    const struct fr_fit_hb *m = fit->hb;
    size_t np1 = fit->np + 1, nx = m->has_dof ? m->ndof * (m->nc + np1) : 0;
    size_t cap = n + MAX_FILL;
    double *block = malloc((n + 4 * cap + 3 * cap * np1 + nx) * sizeof *block);
    size_t *idx = malloc(3 * n * sizeof *idx);
    if (block == NULL || idx == NULL) {
        free(block);
        free(idx);
        return FRICREG_ENOMEM;
    }
    *wk = (struct work){.n = n, .np1 = np1, .cap = cap, .ratio = MAX_RATIO};
    wk->a = block;
    wk->ua = block + n;
    wk->w = wk->ua + cap;
    wk->z = wk->w + cap;
    wk->s = wk->z + cap;
    wk->dw = wk->s + cap;
    wk->dz = wk->dw + cap * np1;
    wk->ds = wk->dz + cap * np1;
    wk->x = wk->ds + cap * np1;
    wk->damp = m->has_dof ? wk->x + m->ndof * m->nc : NULL;
    wk->order = idx;
    wk->pt = idx + n;
    wk->lp = idx + 2 * n;
    return FRICREG_OK;
}

static void free_work(struct work *wk)
{
    free(wk->a);
    free(wk->order);
}

/* Points from ua[u-1] up to a, geometric, each step within the ratio where room allows. */
static void fill_to(struct work *wk, double a, size_t room)
{
    double r = a / wk->ua[wk->u - 1];
    size_t steps = (size_t)ceil(log(r) / log(wk->ratio));
    steps = steps > room + 1 ? room + 1 : steps;
    double base = wk->ua[wk->u - 1];
    for (size_t k = 1; k < steps; k++)
        wk->ua[wk->u++] = base * pow(r, (double)k / (double)steps);
    wk->ua[wk->u++] = a;
}

/* The levels ordered by a (insertion: a few levels) and merged into increasing points, with
 * points between levels farther apart than the ratio: a march's long step may land on another
 * branch (measured on the chain of tests/fit/test_fit_hb.c: a step from a = 1.27 to 2.09 did). */
static void points_of_levels(struct work *wk)
{
    for (size_t i = 0; i < wk->n; i++) {
        size_t k = i;
        for (; k > 0 && wk->a[wk->order[k - 1]] > wk->a[i]; k--)
            wk->order[k] = wk->order[k - 1];
        wk->order[k] = i;
    }
    wk->u = wk->nl = 0;
    for (size_t r = 0; r < wk->n; r++) {
        double a = wk->a[wk->order[r]];
        if (wk->u == 0) {
            wk->ua[wk->u++] = a;
            wk->lp[wk->nl++] = 0;
        } else if (a > wk->ua[wk->u - 1] * (1.0 + SAME)) {
            fill_to(wk, a, wk->cap - wk->u - (wk->n - r));
            wk->lp[wk->nl++] = wk->u - 1;
        }
        wk->pt[wk->order[r]] = wk->u - 1;
    }
}

/* A status of a march that stopped short (no convergence, a singular matrix, ...). */
static int stopped(int st)
{
    return st == FRICREG_EWORK || st == FRICREG_ESINGULAR || st == FRICREG_EINTEGRATOR ||
           st == FRICREG_ENONFINITE;
}

/* A failed driver call's status: a march or a point that stopped (no convergence, a fold, a
 * singular matrix) puts the first level of point k out of reach (*bad); any other (a refused
 * argument, a call from the monitor, no memory) is the model's failure. */
static int driver_failed(fricreg_fit *fit, const struct work *wk, int st, size_t k, size_t *bad)
{
    const char *why = fricreg_hb_errmsg(fit->hb->hb);
    int short_of = stopped(st);
    snprintf(fit->reason, sizeof fit->reason, "%s%s",
             short_of ? "the backbone stops before it: " : "the driver: ", why);
    if (!short_of)
        return st;
    for (size_t r = 0; r < wk->n; r++)
        if (wk->pt[wk->order[r]] >= k) {
            *bad = wk->order[r];
            break;
        }
    return FRICREG_EINVAL;
}

/* The backbone through the points, each point's omega, zeta and S read. A march that stops
 * short is tried again once on the finer points where `refine`: the march's Newton from its
 * secant predictor fails on some grids and not on others (measured on the chain of
 * tests/fit/test_fit_hb.c: 3 of 60 random 6-level grids at Newton's tolerance 1e-12, none with
 * points 1.2 apart). */
static int march(fricreg_fit *fit, struct work *wk, int refine, size_t *bad)
{
    const struct fr_fit_hb *m = fit->hb;
    fit->marches++;
    int st = fricreg_hb_nma_at(m->hb, m->mode, m->damping, wk->u, wk->ua);
    if (st != FRICREG_OK && stopped(st) && refine && wk->ratio > FINE_RATIO) {
        wk->ratio = FINE_RATIO;
        points_of_levels(wk);
        fit->marches++;
        st = fricreg_hb_nma_at(m->hb, m->mode, m->damping, wk->u, wk->ua);
    }
    if (st != FRICREG_OK)
        return driver_failed(fit, wk, st, fricreg_hb_nma_points(m->hb), bad);
    for (size_t l = 0; l < wk->nl; l++) {
        size_t k = wk->lp[l];
        double a;
        st = fricreg_hb_nma_point(m->hb, k, &a, &wk->w[k], &wk->z[k], m->ndof, m->nc,
                                  m->has_dof ? wk->x : NULL);
        if (st != FRICREG_OK)
            return driver_failed(fit, wk, st, k, bad);
        wk->ua[k] = a;
        const double *xd = wk->x + m->nc * m->dof;
        wk->s[k] = m->has_dof ? hypot(xd[1], xd[2]) : fabs(fit->sensor) * a;
    }
    return FRICREG_OK;
}

/* Point k's sensitivities in the parameters from..np1-1 (from = np1 - 1: a alone). */
static int sensitivities(fricreg_fit *fit, struct work *wk, size_t k, size_t from, size_t *bad)
{
    const struct fr_fit_hb *m = fit->hb;
    size_t np1 = wk->np1, cnt = np1 - from;
    double *dw = wk->dw + k * np1 + from, *dz = wk->dz + k * np1 + from;
    int st = fricreg_hb_nma_point_sensitivities(m->hb, k, cnt, m->kind + from, m->first + from,
                                                m->count + from, m->index + from, dw, dz, m->ndof,
                                                m->has_dof ? wk->damp : NULL);
    if (st != FRICREG_OK)
        return driver_failed(fit, wk, st, k, bad);
    for (size_t j = 0; j < cnt; j++) {
        int amplitude = from + j == np1 - 1;
        wk->ds[k * np1 + from + j] = m->has_dof  ? wk->damp[j * m->ndof + m->dof]
                                     : amplitude ? fabs(fit->sensor)
                                                 : 0.0;
    }
    return FRICREG_OK;
}

/* d log g/dp_j at point k (j = np1 - 1: d log g/da). */
static double dlog_g(const struct work *wk, int kind, size_t k, size_t j)
{
    size_t at = k * wk->np1 + j;
    return wk->ds[at] / wk->s[k] + kind * wk->dw[at] / wk->w[k];
}

/* The largest |log g - log A| over the levels. */
static double worst(const struct work *wk, int kind, const double amp[])
{
    double e = 0.0;
    for (size_t i = 0; i < wk->n; i++) {
        size_t k = wk->pt[i];
        e = fmax(e, fabs(log(wk->s[k] * pow(wk->w[k], kind)) - log(amp[i])));
    }
    return e;
}

/* Each level's Newton step on log a (the points' slopes found). */
static int newton_step(fricreg_fit *fit, struct work *wk, int kind, const double amp[], size_t *bad)
{
    size_t a_col = wk->np1 - 1;
    for (size_t l = 0; l < wk->nl; l++) {
        int st = sensitivities(fit, wk, wk->lp[l], a_col, bad);
        if (st != FRICREG_OK)
            return st;
    }
    for (size_t i = 0; i < wk->n; i++) {
        size_t k = wk->pt[i];
        double slope = wk->ua[k] * dlog_g(wk, kind, k, a_col);
        if (!(slope > 0.0)) { /* a fold of the measured amplitude */
            *bad = i;
            snprintf(fit->reason, sizeof fit->reason,
                     "the measured amplitude folds at the modal amplitude %g", wk->ua[k]);
            return FRICREG_EINVAL;
        }
        double e = log(wk->s[k] * pow(wk->w[k], kind)) - log(amp[i]);
        wk->a[i] = wk->ua[k] * exp(fmax(-MAX_LOG_STEP, fmin(MAX_LOG_STEP, -e / slope)));
    }
    points_of_levels(wk);
    return FRICREG_OK;
}

/* Every level's first a: the caller's guess; A/|s| for a displacement at the modal sensor;
 * else the linear mode's ratio from a probe march far below any slip. */
static int first_amplitudes(fricreg_fit *fit, struct work *wk, int kind, const double amp[],
                            const double guess[], size_t *bad)
{
    int exact = kind == FRICREG_FIT_DISPLACEMENT && !fit->hb->has_dof, probe = 0;
    double lo = INFINITY;
    for (size_t i = 0; i < wk->n; i++) {
        wk->a[i] = exact ? amp[i] / fabs(fit->sensor) : guess[i];
        probe |= isnan(wk->a[i]);
        lo = fmin(lo, amp[i]);
    }
    if (probe) {
        wk->u = wk->nl = 1;
        wk->ua[0] = PROBE * lo;
        wk->lp[0] = 0;
        for (size_t i = 0; i < wk->n; i++)
            wk->pt[i] = 0, wk->order[i] = i;
        int st = march(fit, wk, 0, bad);
        if (st != FRICREG_OK)
            return st;
        double gain = wk->s[0] / wk->ua[0] * pow(wk->w[0], kind);
        for (size_t i = 0; i < wk->n; i++)
            wk->a[i] = isnan(wk->a[i]) ? amp[i] / gain : wk->a[i];
    }
    points_of_levels(wk);
    return FRICREG_OK;
}

/* 1 if a march's error rose where Newton's method was converging: the march took another
 * branch than the last one at nearly the same amplitudes (measured on tests/fit/test_fit_hb.c's
 * chain: from 1.8e-5 to 4.0 at a step of 3e-5 in a, the error then cycling between two). */
static int jumped(double e, double last)
{
    return last < JUMP_NEAR && e > JUMP_RISE * last + NEWTON_TOL;
}

/* The levels' modal amplitudes solved: the last march's points are at them. A march that
 * jumped is marched again on the finer points once; jumping again, the levels are out of
 * reach. */
static int solve_amplitudes(fricreg_fit *fit, struct work *wk, int kind, const double amp[],
                            size_t *bad)
{
    double last = INFINITY;
    for (int it = 0; it < NEWTON_MAX; it++) {
        int st = march(fit, wk, 1, bad);
        double e = st == FRICREG_OK ? worst(wk, kind, amp) : 0.0;
        if (st == FRICREG_OK && jumped(e, last) && wk->ratio > FINE_RATIO) {
            wk->ratio = FINE_RATIO;
            points_of_levels(wk);
            st = march(fit, wk, 0, bad);
            e = st == FRICREG_OK ? worst(wk, kind, amp) : 0.0;
        }
        if (st != FRICREG_OK)
            return st;
        if (jumped(e, last))
            break;
        if (e <= NEWTON_TOL)
            return FRICREG_OK;
        last = e;
        st = newton_step(fit, wk, kind, amp, bad);
        if (st != FRICREG_OK)
            return st;
    }
    *bad = wk->order[wk->n - 1];
    snprintf(fit->reason, sizeof fit->reason,
             "Newton's method on the modal amplitudes did not converge in %d marches, or the "
             "backbone jumped between branches near them",
             NEWTON_MAX);
    return FRICREG_EINVAL;
}

/* The total derivatives at each level (the header comment's), into out. */
static void levels_out(const fricreg_fit *fit, const struct work *wk, int kind,
                       const struct fr_fit_levels *out, double guess[])
{
    size_t np = fit->np, a_col = np;
    for (size_t i = 0; i < wk->n; i++) {
        size_t k = wk->pt[i], at = k * wk->np1;
        double ga = dlog_g(wk, kind, k, a_col);
        out->freq_hz[i] = wk->w[k] / FR_TWO_PI;
        out->zeta[i] = wk->z[k];
        out->modal[i] = guess[i] = wk->ua[k];
        for (size_t j = 0; j < np; j++) {
            double da = -dlog_g(wk, kind, k, j) / ga;
            out->dfreq[i * np + j] = (wk->dw[at + j] + wk->dw[at + a_col] * da) / FR_TWO_PI;
            out->dzeta[i * np + j] = wk->dz[at + j] + wk->dz[at + a_col] * da;
        }
    }
}

int fr_fit_hb_levels(fricreg_fit *fit, int kind, size_t n, const double amp[], double guess[],
                     const struct fr_fit_levels *out, size_t *bad)
{
    struct work wk;
    if (alloc_work(fit, n, &wk) != FRICREG_OK) {
        snprintf(fit->reason, sizeof fit->reason, "out of memory for %zu levels", n);
        return FRICREG_ENOMEM;
    }
    int st = first_amplitudes(fit, &wk, kind, amp, guess, bad);
    if (st == FRICREG_OK)
        st = solve_amplitudes(fit, &wk, kind, amp, bad);
    for (size_t l = 0; l < wk.nl && st == FRICREG_OK; l++)
        st = sensitivities(fit, &wk, wk.lp[l], 0, bad);
    if (st == FRICREG_OK)
        levels_out(fit, &wk, kind, out, guess);
    free_work(&wk);
    return st;
}
