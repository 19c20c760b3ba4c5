/* SPDX-License-Identifier: GPL-3.0-or-later */
/* exact.c — the semi-analytical solution of Eq. (5) under Coulomb friction (1) with force
 * balance at rest (2): closed forms on each phase, switching times by GSL's Brent solver.
 *
 * A phase is a stick (x constant, x' = 0, while |f_eq| <= mun) or a slip in direction s,
 * on which x'' + x = -s mun + a sin(omega t) has the closed form of slip_state(). Each phase
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
#include "fricreg_exact.h"

#define SCAN_PER_PERIOD 1024.0
#define MAX_CYCLES 1e6
#define BRENT_MAX_ITER 200
#define START_REFINEMENTS 40                 /* halvings of the first scan step at a phase start */
#define EMPTY_PHASE (64.0 * GSL_DBL_EPSILON) /* a phase this short (relative to t) has no length */
#define N_STATS 3
/* Work limits of one run (documented in fricreg_exact.h): seconds and 128 MiB at most. */
#define MAX_PHASES (1L << 22)
#define MAX_SCAN_POINTS (1LL << 27)
/* A scan step below this many ulps of t has lost the time resolution the closed forms need. */
#define MIN_STEP_RELATIVE 0x1p-32

struct phase {
    double t0, x0, v0;
    int s; /* 0: stick; +1 or -1: slip in that direction */
};

struct fricreg_exact {
    double a, omega, mun, x0, v0; /* as given to fricreg_exact_create */
    double t_end;                 /* end of the solution held; 0 before the first run */
    struct phase *ph;             /* its phases; ph[0] starts at t = 0 */
    size_t n, cap;
    int64_t stats[N_STATS];  /* enum fricreg_exact_stat, of the solution held */
    gsl_root_fsolver *brent; /* allocated at create: a run allocates only phases */
    struct fr_error err;
};

/* The forced response to a sin(omega t) and its rate: a sin(wt)/(1 - w^2), or at resonance
 * the secular -(a/2) t cos t. */
static void forced(const fricreg_exact *ex, double t, double *xp, double *vp)
{
    double a = ex->a, w = ex->omega;
    if (w == 1.0) {
        *xp = -0.5 * a * t * cos(t);
        *vp = -0.5 * a * cos(t) + 0.5 * a * t * sin(t);
    } else {
        double P = a / (1.0 - w * w);
        *xp = P * sin(w * t);
        *vp = P * w * cos(w * t);
    }
}

/* Closed-form state in phase p at time t (Eq. (5) with f = -s mun constant). */
static void phase_state(const fricreg_exact *ex, const struct phase *p, double t, double *x,
                        double *v)
{
    if (p->s == 0) {
        *x = p->x0;
        *v = 0.0;
        return;
    }
    double c = -p->s * ex->mun, xp0, vp0, xp, vp;
    forced(ex, p->t0, &xp0, &vp0);
    forced(ex, t, &xp, &vp);
    double A = p->x0 - c - xp0, B = p->v0 - vp0, tau = t - p->t0;
    *x = c + xp + A * cos(tau) + B * sin(tau);
    *v = vp - A * sin(tau) + B * cos(tau);
}

static double f_eq(const fricreg_exact *ex, double x, double t)
{
    return x - ex->a * sin(ex->omega * t);
}

struct phase_probe {
    const fricreg_exact *ex;
    const struct phase *p;
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
    phase_state(pr->ex, pr->p, t, &x, &v);
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
    const struct phase *p = pr->p;
    double x, v, a = fabs(e->a), w = e->omega;
    ex->stats[FRICREG_EXACT_STAT_SCAN_POINTS]++;
    phase_state(e, p, t, &x, &v);
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
static double min_step(const fricreg_exact *ex, const struct phase *p)
{
    double forcing = FR_TWO_PI / ex->omega;
    return (p->s == 0 ? forcing : fmin(forcing, FR_TWO_PI)) / SCAN_PER_PERIOD;
}

/* M >= |g''| on the whole slip p away from resonance: |x_p'''| = |P| omega^3 plus the free
 * oscillation's amplitude sqrt(A^2 + B^2); often tighter than scan_point's bound. */
static double slip_curvature_bound(const fricreg_exact *ex, const struct phase *p)
{
    double a = fabs(ex->a), w = ex->omega, xp0, vp0;
    if (p->s == 0 || w == 1.0)
        return HUGE_VAL;
    forced(ex, p->t0, &xp0, &vp0);
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
static int sticks_for_ever(const fricreg_exact *ex, const struct phase *p)
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
static int phase_end(fricreg_exact *ex, const struct phase *p, double *t_end, int *ends,
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

static int push_phase(fricreg_exact *ex, struct phase p)
{
    if (ex->n == ex->cap) {
        size_t cap = ex->cap ? 2 * ex->cap : 64;
        struct phase *ph = realloc(ex->ph, cap * sizeof *ph);
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
static struct phase from_rest(const fricreg_exact *ex, double t, double x)
{
    int sticks = fabs(f_eq(ex, x, t)) <= ex->mun + stick_slack(ex, x);
    return (struct phase){t, x, 0.0, sticks ? 0 : breakaway_direction(ex, t, x)};
}

/* Records why solve() stopped at phase p (a stick if p->s is 0) and returns status. */
static int solve_failed(const fricreg_exact *ex, const struct phase *p, int status, int no_progress,
                        struct fr_error *err)
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

/* The phases from t = 0 to ex->t_end into ex->ph, which is empty. A phase of zero length (a
 * stick broken at once, a slip with no motion) is replaced by its successor, so no switch is
 * reported for it; two in a row would mean no progress, which the closed forms exclude. */
static int solve(fricreg_exact *ex, struct fr_error *err)
{
    struct phase p = ex->v0 != 0.0 ? (struct phase){0.0, ex->x0, ex->v0, ex->v0 > 0.0 ? 1 : -1}
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
        phase_state(ex, &p, t1, &x, &v);
        /* A slip ends at rest; a stick ends in a slip. */
        struct phase next = p.s != 0 ? from_rest(ex, t1, x)
                                     : (struct phase){t1, x, 0.0, breakaway_direction(ex, t1, x)};
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

int fricreg_exact_create(double a, double omega, double mun, double x0, double v0,
                         fricreg_exact **out)
{
    if (out == NULL)
        return FRICREG_ENULL;
    if (!isfinite(a) || !isfinite(omega) || !isfinite(mun) || !isfinite(x0) || !isfinite(v0))
        return FRICREG_ENONFINITE;
    if (!(omega > 0.0) || !(mun >= 0.0))
        return FRICREG_EINVAL;
    fricreg_exact *ex = calloc(1, sizeof *ex);
    if (ex == NULL)
        return FRICREG_ENOMEM;
    *ex = (fricreg_exact){.a = a, .omega = omega, .mun = mun, .x0 = x0, .v0 = v0};
    /* gsl_root_fsolver_alloc's two mallocs, done here: GSL would report a failed one to its
     * error handler, which aborts by default. */
    ex->brent = malloc(sizeof *ex->brent);
    void *state = malloc(gsl_root_fsolver_brent->size);
    if (ex->brent == NULL || state == NULL) {
        free(ex->brent);
        free(state);
        free(ex);
        return FRICREG_ENOMEM;
    }
    *ex->brent = (gsl_root_fsolver){.type = gsl_root_fsolver_brent, .state = state};
    *out = ex;
    return FRICREG_OK;
}

static double period(const fricreg_exact *ex)
{
    return FR_TWO_PI / ex->omega;
}

/* Solves into a copy, so that a failed run leaves the solution held as it was. */
static int run_to(fricreg_exact *ex, double t_end)
{
    fricreg_exact work = *ex;
    work.t_end = t_end;
    work.ph = NULL;
    work.n = work.cap = 0;
    for (int k = 0; k < N_STATS; k++)
        work.stats[k] = 0;
    int status = solve(&work, &ex->err);
    if (status != FRICREG_OK) {
        free(work.ph);
        return status;
    }
    free(ex->ph);
    ex->t_end = work.t_end;
    ex->ph = work.ph;
    ex->n = work.n;
    ex->cap = work.cap;
    for (int k = 0; k < N_STATS; k++)
        ex->stats[k] = work.stats[k];
    return FRICREG_OK;
}

int fricreg_exact_run(fricreg_exact *ex, double t_end)
{
    if (ex == NULL)
        return FRICREG_ENULL;
    if (!isfinite(t_end))
        return fr_error_set(&ex->err, FRICREG_ENONFINITE, "run: t_end = %g is not finite", t_end);
    if (!(t_end > 0.0))
        return fr_error_set(&ex->err, FRICREG_EINVAL, "run: t_end = %g must be > 0", t_end);
    if (t_end * ex->omega / FR_TWO_PI > MAX_CYCLES)
        return fr_error_set(&ex->err, FRICREG_EINVAL,
                            "run: t_end = %g spans %g forcing cycles "
                            "of period %g, more than 10^6",
                            t_end, t_end / period(ex), period(ex));
    return run_to(ex, t_end);
}

int fricreg_exact_run_cycles(fricreg_exact *ex, int cycles)
{
    if (ex == NULL)
        return FRICREG_ENULL;
    if (cycles < 1 || cycles > MAX_CYCLES)
        return fr_error_set(&ex->err, FRICREG_EINVAL,
                            "run_cycles: cycles = %d must be from 1 to 10^6", cycles);
    return run_to(ex, cycles * period(ex));
}

/* 1.0's one-call form: create, run, and the object only if both succeed. A non-finite t_end
 * is checked first, as 1.0 checked every number before any range. */
int fricreg_exact_solve(double a, double omega, double mun, double x0, double v0, double t_end,
                        fricreg_exact **out)
{
    if (out == NULL)
        return FRICREG_ENULL;
    if (!isfinite(t_end))
        return FRICREG_ENONFINITE;
    fricreg_exact *ex = NULL;
    int status = fricreg_exact_create(a, omega, mun, x0, v0, &ex);
    if (status == FRICREG_OK)
        status = fricreg_exact_run(ex, t_end);
    if (status != FRICREG_OK) {
        fricreg_exact_free(ex);
        return status;
    }
    *out = ex;
    return FRICREG_OK;
}

void fricreg_exact_free(fricreg_exact *ex)
{
    if (ex == NULL)
        return;
    free(ex->brent->state);
    free(ex->brent);
    free(ex->ph);
    free(ex);
}

int fricreg_exact_errcode(const fricreg_exact *ex)
{
    return ex ? ex->err.code : FRICREG_OK;
}

const char *fricreg_exact_errmsg(const fricreg_exact *ex)
{
    return ex ? ex->err.msg : "NULL exact solution";
}

size_t fricreg_exact_errmsg_copy(const fricreg_exact *ex, char *buf, size_t len)
{
    return fr_error_copy(fricreg_exact_errmsg(ex), buf, len);
}

int fricreg_exact_get_value(const fricreg_exact *ex, int which, double *value)
{
    if (ex == NULL || value == NULL)
        return FRICREG_ENULL;
    switch (which) {
    case FRICREG_EXACT_VALUE_TIME: *value = ex->t_end; return FRICREG_OK;
    case FRICREG_EXACT_VALUE_PERIOD: *value = period(ex); return FRICREG_OK;
    default: return FRICREG_EINVAL;
    }
}

int fricreg_exact_get_stat(const fricreg_exact *ex, int which, int64_t *value)
{
    if (ex == NULL || value == NULL)
        return FRICREG_ENULL;
    if (which < 0 || which >= N_STATS)
        return FRICREG_EINVAL;
    *value = ex->stats[which];
    return FRICREG_OK;
}

/* Index of the phase holding time t: the last one that starts at or before t. */
static size_t phase_at(const fricreg_exact *ex, double t)
{
    size_t lo = 0, hi = ex->n;
    while (hi - lo > 1) {
        size_t mid = lo + (hi - lo) / 2;
        if (ex->ph[mid].t0 <= t)
            lo = mid;
        else
            hi = mid;
    }
    return lo;
}

int fricreg_exact_state(const fricreg_exact *ex, double t, double *x, double *v)
{
    if (ex == NULL || x == NULL || v == NULL)
        return FRICREG_ENULL;
    if (ex->n == 0 || !(t >= 0.0 && t <= ex->t_end))
        return FRICREG_EINVAL;
    phase_state(ex, &ex->ph[phase_at(ex, t)], t, x, v);
    return FRICREG_OK;
}

size_t fricreg_exact_nswitches(const fricreg_exact *ex)
{
    return ex && ex->n > 0 ? ex->n - 1 : 0;
}

int fricreg_exact_switches(const fricreg_exact *ex, size_t n, double times[], int sticks[])
{
    if (ex == NULL || (times == NULL && n > 0))
        return FRICREG_ENULL;
    if (n != fricreg_exact_nswitches(ex))
        return FRICREG_ESIZE;
    for (size_t k = 0; k < n; k++) {
        times[k] = ex->ph[k + 1].t0;
        if (sticks != NULL)
            sticks[k] = ex->ph[k + 1].s == 0;
    }
    return FRICREG_OK;
}

size_t fricreg_exact_ncycles(const fricreg_exact *ex)
{
    return ex ? (size_t)fr_whole_cycles(ex->t_end, period(ex)) : 0;
}

/* Phase k covers [t0_k, t0_{k+1}); the last one ends at t_end. Overlap with [ta, tb]. */
static int overlap(const fricreg_exact *ex, size_t k, double ta, double tb, double *lo, double *hi)
{
    double end = k + 1 < ex->n ? ex->ph[k + 1].t0 : ex->t_end;
    *lo = fmax(ta, ex->ph[k].t0);
    *hi = fmin(tb, end);
    return *hi > *lo;
}

/* Distance slid in [ta, tb]: on a slip x is monotone, so it is |x(hi) - x(lo)| per phase. */
static double slid(const fricreg_exact *ex, double ta, double tb)
{
    double total = 0.0, lo, hi, x_lo, x_hi, v;
    for (size_t k = phase_at(ex, ta); k < ex->n && ex->ph[k].t0 < tb; k++) {
        if (ex->ph[k].s == 0 || !overlap(ex, k, ta, tb, &lo, &hi))
            continue;
        phase_state(ex, &ex->ph[k], lo, &x_lo, &v);
        phase_state(ex, &ex->ph[k], hi, &x_hi, &v);
        total += fabs(x_hi - x_lo);
    }
    return total;
}

int fricreg_exact_dissipation(const fricreg_exact *ex, size_t ncycles, double D[])
{
    if (ex == NULL || (D == NULL && ncycles > 0))
        return FRICREG_ENULL;
    if (ncycles != fricreg_exact_ncycles(ex))
        return FRICREG_ESIZE;
    double T = period(ex);
    /* -∫ x' f dt = mun ∫ |x'| dt on a slip; without friction nothing is dissipated, even where
     * the distance slid overflows (x0 near DBL_MAX: 0 * inf; tests/fuzz/regressions/exact/). */
    for (size_t k = 0; k < ncycles; k++)
        D[k] = ex->mun == 0.0 ? 0.0 : ex->mun * slid(ex, (double)k * T, (double)(k + 1) * T);
    return FRICREG_OK;
}

int fricreg_exact_stick_fraction(const fricreg_exact *ex, double t0, double t1, double *fraction)
{
    if (ex == NULL || fraction == NULL)
        return FRICREG_ENULL;
    if (!(t0 >= 0.0 && t1 > t0 && t1 <= ex->t_end))
        return FRICREG_EINVAL;
    double at_rest = 0.0, lo, hi;
    for (size_t k = phase_at(ex, t0); k < ex->n && ex->ph[k].t0 < t1; k++)
        if (ex->ph[k].s == 0 && overlap(ex, k, t0, t1, &lo, &hi))
            at_rest += hi - lo;
    *fraction = at_rest / (t1 - t0);
    return FRICREG_OK;
}
