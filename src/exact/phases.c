/* SPDX-License-Identifier: GPL-3.0-or-later */
/* phases.c — the phases of the exact solution from t = 0 to t_end (phases.h), under Coulomb
 * friction (1) with force balance at rest (2).
 *
 * A phase is a stick (x constant, x' = 0, while |f_eq| <= mun) or a slip in direction s,
 * on which x'' + x = -s mun + a sin(omega t) has the closed form of fr_exact_phase_state (closed_form.c). Each phase
 * ends at the first root of its own "phase holds" function g, bracketed by a scan and refined
 * with Brent to the last bits. The scan steps by g/L, L a bound on |g'|, which no root can be
 * skipped by, but never by less than 1/1024 of the shortest period the phase's g contains
 * (the forcing for a stick; the forcing and the free period 2 pi for a slip). The work is
 * bounded: a run that needs more switches or scan points than the limits below, or a step
 * lost in the rounding of t, is refused instead of running for hours. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>

#include "base/error.h"
#include "base/fr_math.h"
#include "closed_form.h"
#include "phases.h"

#define SCAN_PER_PERIOD 1024.0
#define BRENT_MAX_ITER 200
#define START_REFINEMENTS 40                 /* halvings of the first scan step at a phase start */
#define EMPTY_PHASE (64.0 * GSL_DBL_EPSILON) /* a phase this short (relative to t) has no length */
/* Work limits of one run (documented in fricreg_exact.h): seconds and 128 MiB at most. */
#define MAX_PHASES (1L << 22)
#define MAX_SCAN_POINTS (1LL << 27)
/* A scan step below this many ulps of t has lost the time resolution the closed forms need. */
#define MIN_STEP_RELATIVE 0x1p-32

static double f_eq(const fricreg_exact *ex, double x, double t)
{
    return x - ex->a * sin(ex->omega * t);
}

struct phase_probe {
    const fricreg_exact *ex;
    const struct fr_phase *p;
    int slack; /* add the stick's slack (stick_slack) */
};

/* A stick holds while |f_eq| <= mun, the force balance (2); rounding in x at the switch
 * that started it must not break it, so the bound gets a few ulps of slack (which moves a
 * breakaway by ~1e-15). The floor keeps a stick with mun = a = x = 0 alive. */
static double stick_slack(const fricreg_exact *ex, double x)
{
    return 4.0 * GSL_DBL_EPSILON * (ex->mun + fabs(ex->a) + fabs(x)) + GSL_DBL_MIN;
}

/* Positive while the phase holds: s x' for a slip, mun - |f_eq| (+ slack) for a stick. */
static double holds(double t, void *params)
{
    const struct phase_probe *pr = params;
    double x, v;
    fr_exact_phase_state(pr->ex, pr->p, t, &x, &v);
    if (pr->p->s != 0)
        return pr->p->s * v;
    return pr->ex->mun - fabs(f_eq(pr->ex, x, t)) + (pr->slack ? stick_slack(pr->ex, x) : 0.0);
}

/* holds() for Brent, kept finite: GSL reports a non-finite value to its error handler, and
 * only the sign matters for the bracket (a NaN, never seen, counts as "fails"). */
static double holds_finite(double t, void *params)
{
    double g = holds(t, params);
    if (isnan(g))
        return -1.0;
    return fmax(-GSL_DBL_MAX, fmin(g, GSL_DBL_MAX));
}

/* Brent on [lo, hi] with holds(lo) > 0 >= holds(hi): the first time the phase fails. The
 * slack only has to carry a stick over its first instants: where lo is clear of them, the
 * root is that of the exact condition |f_eq| = mun. The bracket is valid and ordered, and
 * the function finite, so GSL has nothing to report to its error handler. */
static int refine(fricreg_exact *ex, struct phase_probe *pr, double lo, double hi, double *root)
{
    struct phase_probe exact = *pr;
    exact.slack = 0;
    if (holds(lo, &exact) > 0.0)
        pr = &exact;
    ex->stats[FRICREG_EXACT_STAT_ROOTS]++;
    if (holds(hi, pr) == 0.0) {
        *root = hi;
        return FRICREG_OK;
    }
    gsl_function F = {holds_finite, pr};
    gsl_root_fsolver *s = ex->brent;
    int status = gsl_root_fsolver_set(s, &F, lo, hi);
    for (int it = 0; status == GSL_SUCCESS && it < BRENT_MAX_ITER; it++) {
        status = gsl_root_fsolver_iterate(s);
        ex->stats[FRICREG_EXACT_STAT_ROOT_ITERS]++;
        lo = gsl_root_fsolver_x_lower(s);
        hi = gsl_root_fsolver_x_upper(s);
        if (status == GSL_SUCCESS &&
            gsl_root_test_interval(lo, hi, 0.0, 2.0 * GSL_DBL_EPSILON) == GSL_SUCCESS)
            break;
    }
    *root = gsl_root_fsolver_root(s);
    return status == GSL_SUCCESS ? FRICREG_OK : FRICREG_EINTEGRATOR;
}

/* How far one scan step may reach in a slip, so that the bound M below holds over it. */
#define SLIP_REACH FR_TWO_PI

/* A scan point of phase_end, counted: g = holds(t), a lower bound dg on g'(t) and a bound M
 * on |g''| over the next step.
 * Stick: g = mun - |f_eq| may turn either way, dg = -|d f_eq/dt|, M = |a| omega^2.
 * Slip: dg = s x'' from Eq. (5), and g'' = s x''' = s (a omega cos(omega t) - x'). With
 * y = x + s mun, E = y^2 + x'^2 has dE/dt = 2 x' a sin(omega t), so sqrt(E) grows at most by
 * |a| per unit time and |x'''| <= sqrt(E(t)) + |a| (SLIP_REACH + omega) over a step of at
 * most SLIP_REACH, at resonance too, where the closed form's terms grow as t. */
static double scan_point(fricreg_exact *ex, double t, struct phase_probe *pr, double *dg, double *M)
{
    const fricreg_exact *e = pr->ex;
    const struct fr_phase *p = pr->p;
    double x, v, a = fabs(e->a), w = e->omega;
    ex->stats[FRICREG_EXACT_STAT_SCAN_POINTS]++;
    fr_exact_phase_state(e, p, t, &x, &v);
    if (p->s != 0) {
        *dg = p->s * (-x - p->s * e->mun + e->a * sin(w * t));
        *M = hypot(x + p->s * e->mun, v) + a * (SLIP_REACH + w);
    } else {
        *dg = -fabs(e->a * w * cos(w * t));
        *M = a * w * w;
    }
    return holds(t, pr);
}

/* The smallest scan step of phase p: 1/1024 of the shortest period in its g — the forcing's
 * for a stick (g = mun - |x - a sin(omega t)|), also the free period 2 pi for a slip. */
static double min_step(const fricreg_exact *ex, const struct fr_phase *p)
{
    double forcing = FR_TWO_PI / ex->omega;
    return (p->s == 0 ? forcing : fmin(forcing, FR_TWO_PI)) / SCAN_PER_PERIOD;
}

/* M >= |g''| on the whole slip p away from resonance: |x_p'''| = |P| omega^3 plus the free
 * oscillation's amplitude sqrt(A^2 + B^2); often tighter than scan_point's bound. */
static double slip_curvature_bound(const fricreg_exact *ex, const struct fr_phase *p)
{
    double a = fabs(ex->a), w = ex->omega, xp0, vp0;
    if (p->s == 0 || w == 1.0)
        return HUGE_VAL;
    fr_exact_forced(ex, p->t0, &xp0, &vp0);
    return a * w * w * w / fabs(1.0 - w * w) + hypot(p->x0 + p->s * ex->mun - xp0, p->v0 - vp0);
}

/* The largest s with g + dg s - M s^2/2 > 0 on [0, s): by Taylor's bound g keeps its sign
 * that long, so no root lies closer to the scan point (g > 0, M >= |g''|). */
static double safe_step(double g, double dg, double M)
{
    if (M > 0.0) {
        double root = sqrt(dg * dg + 2.0 * M * g);
        return dg >= 0.0 ? (dg + root) / M : 2.0 * g / (root - dg);
    }
    return dg >= 0.0 ? HUGE_VAL : g / -dg;
}

/* A stick that cannot end: |f_eq| <= |x| + |a| <= mun for every t. */
static int sticks_for_ever(const fricreg_exact *ex, const struct fr_phase *p)
{
    return p->s == 0 && fabs(p->x0) + fabs(ex->a) <= ex->mun;
}

static int work_refused(const fricreg_exact *ex, struct fr_error *err, double t, const char *what)
{
    return fr_error_set(err, FRICREG_EINVAL,
                        "run: refused at t = %.17g of t_end = %g: %s (limits: %ld switches, %lld"
                        " scan points, steps above 2^-32 t); shorten t_end",
                        t, ex->t_end, what, (long)MAX_PHASES - 1, (long long)MAX_SCAN_POINTS);
}

/* The end of phase p: the first t > t0 where it stops holding, or t_end. *ends says which. */
static int phase_end(fricreg_exact *ex, const struct fr_phase *p, double *t_end, int *ends,
                     struct fr_error *err)
{
    struct phase_probe pr = {ex, p, 1};
    double h = min_step(ex, p), M_phase = slip_curvature_bound(ex, p), g = 0.0, dg = 0.0, M = 0.0;
    *ends = 0;
    *t_end = ex->t_end;
    if (sticks_for_ever(ex, p))
        return FRICREG_OK;
    if (h < p->t0 * MIN_STEP_RELATIVE)
        return work_refused(ex, err, p->t0, "the scan step is lost in the rounding of t");
    /* At the start the phase function is 0 (x' = 0, or |f_eq| = mun): find a first point
     * where it is positive, halving the step; none means the phase has no length. */
    double lo = p->t0 + h;
    int k = 0;
    while (k < START_REFINEMENTS && lo > p->t0 &&
           !((g = scan_point(ex, fmin(lo, ex->t_end), &pr, &dg, &M)) > 0.0))
        lo = p->t0 + h * ldexp(1.0, -++k);
    if (k == START_REFINEMENTS || !(lo > p->t0)) {
        *ends = 1;
        *t_end = p->t0;
        return FRICREG_OK;
    }
    /* Scan on by safe steps of at least h (which the first halved steps may have been below). */
    while (lo < ex->t_end) {
        if (ex->stats[FRICREG_EXACT_STAT_SCAN_POINTS] >= MAX_SCAN_POINTS)
            return work_refused(ex, err, lo, "too many scan points");
        double reach = p->s != 0 ? SLIP_REACH : HUGE_VAL;
        double hi = fmin(lo + fmax(h, fmin(reach, safe_step(g, dg, fmin(M, M_phase)))), ex->t_end);
        double g_hi = scan_point(ex, hi, &pr, &dg, &M);
        if (isnan(g_hi) || isinf(g_hi))
            return fr_error_set(err, FRICREG_EDIVERGED,
                                "run: the closed form overflows at t = %.17g", hi);
        if (!(g_hi > 0.0)) {
            *ends = 1;
            return refine(ex, &pr, lo, hi, t_end);
        }
        lo = hi;
        g = g_hi;
    }
    return FRICREG_OK;
}

static int push_phase(fricreg_exact *ex, struct fr_phase p)
{
    if (ex->n == ex->cap) {
        size_t cap = ex->cap ? 2 * ex->cap : 64;
        struct fr_phase *ph = realloc(ex->ph, cap * sizeof *ph);
        if (ph == NULL)
            return FRICREG_ENOMEM;
        ex->ph = ph;
        ex->cap = cap;
    }
    ex->ph[ex->n++] = p;
    return FRICREG_OK;
}

/* Direction of a slip that starts from rest at (t, x): towards the free acceleration -f_eq,
 * or, where f_eq is 0 (mun = 0), towards where it goes next: -df_eq/dt = a w cos(wt). */
static int breakaway_direction(const fricreg_exact *ex, double t, double x)
{
    double feq = f_eq(ex, x, t);
    double towards = fabs(feq) > stick_slack(ex, x) ? -feq : ex->a * ex->omega * cos(ex->omega * t);
    return towards < 0.0 ? -1 : 1;
}

/* The phase that starts at rest at (t, x): a stick if the force balance (2) holds, else a
 * slip. */
static struct fr_phase from_rest(const fricreg_exact *ex, double t, double x)
{
    int sticks = fabs(f_eq(ex, x, t)) <= ex->mun + stick_slack(ex, x);
    return (struct fr_phase){t, x, 0.0, sticks ? 0 : breakaway_direction(ex, t, x)};
}

/* Records why fr_exact_phases stopped at phase p (a stick if p->s is 0) and returns status. */
static int solve_failed(const fricreg_exact *ex, const struct fr_phase *p, int status,
                        int no_progress, struct fr_error *err)
{
    if (status == FRICREG_ENOMEM)
        return fr_error_set(err, status, "run: out of memory at phase %zu, t = %.17g", ex->n,
                            p->t0);
    if (no_progress)
        return fr_error_set(err, status,
                            "run: no progress at t = %.17g: two phases of zero "
                            "length in a row",
                            p->t0);
    return fr_error_set(err, status,
                        "run: Brent's method failed on the end of the %s that "
                        "starts at t = %.17g",
                        p->s == 0 ? "stick" : "slip", p->t0);
}

int fr_exact_phases(fricreg_exact *ex, struct fr_error *err)
{
    struct fr_phase p = ex->v0 != 0.0
                            ? (struct fr_phase){0.0, ex->x0, ex->v0, ex->v0 > 0.0 ? 1 : -1}
                            : from_rest(ex, 0.0, ex->x0);
    int empty_in_a_row = 0;
    for (;;) {
        if (ex->n == MAX_PHASES)
            return work_refused(ex, err, p.t0, "too many switches");
        int status = push_phase(ex, p);
        double t1 = p.t0, x, v;
        int ends = 0;
        if (status == FRICREG_OK)
            status = phase_end(ex, &p, &t1, &ends, err);
        if (status == FRICREG_EINVAL || status == FRICREG_EDIVERGED)
            return status; /* phase_end wrote the message */
        if (status != FRICREG_OK)
            return solve_failed(ex, &p, status, 0, err);
        if (!ends)
            return FRICREG_OK;
        fr_exact_phase_state(ex, &p, t1, &x, &v);
        /* A slip ends at rest; a stick ends in a slip. */
        struct fr_phase next = p.s != 0
                                   ? from_rest(ex, t1, x)
                                   : (struct fr_phase){t1, x, 0.0, breakaway_direction(ex, t1, x)};
        if (t1 <= p.t0 + EMPTY_PHASE * fmax(1.0, p.t0)) {
            if (++empty_in_a_row == 2)
                return solve_failed(ex, &p, FRICREG_EINTEGRATOR, 1, err);
            ex->n--;
            next.t0 = p.t0; /* the successor takes its place, from the same state */
            next.x0 = p.x0;
        } else {
            empty_in_a_row = 0;
        }
        p = next;
    }
}
