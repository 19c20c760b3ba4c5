/* SPDX-License-Identifier: GPL-3.0-or-later */
/* extrapolate.c — fricreg_sim_run_extrapolated: the same run at eps, eps/2, …, and D
 * extrapolated to eps -> 0 (richardson.h), with its error estimate.
 *
 * Level 0 is the caller's simulation itself; the finer levels are fresh simulations with
 * its settings, so a level never sees another's state, except with a window
 * (fricreg_sim_run_extrapolated_window): then they start from level 0's state at the
 * beginning of the window's last cycles. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/fr_math.h"
#include "richardson.h"
#include "sim_internal.h"

/* Runs level k to t_end into D[k * ncycles …] and total[k]; a failure is reported on sim.
 * With first > 0 (a window) it starts at the end of cycle `first` from level 0's state there,
 * start_y, and fills the cycles from `first` on. */
static int run_level(fricreg_sim *sim, int k, double t_end, size_t first, const double *start_y,
                     double D[], double total[], int64_t *rhs_evals)
{
    fricreg_sim *level = NULL;
    int status = fr_sim_level(sim, k, 1.0, &level);
    if (status != FRICREG_OK)
        return fr_fail(sim, status, "run_extrapolated: level %d: out of memory", k);
    level->start_cycle = first;
    level->start_y = first > 0 ? start_y : NULL;
    status = fricreg_sim_run(level, t_end);
    if (status == FRICREG_OK && level->cycles + first != sim->cycles)
        status = fr_fail(level, FRICREG_EINTEGRATOR, "completed %zu cycles, level 0 %zu",
                         level->cycles + first, sim->cycles);
    if (status != FRICREG_OK) {
        fr_fail(sim, status, "run_extrapolated: level %d (eps = %g, dt = %g): %s", k, level->eps,
                level->dt, fricreg_sim_errmsg(level));
        fricreg_sim_free(level);
        return status;
    }
    if (level->cycles > 0)
        memcpy(D + (size_t)k * sim->cycles + first, level->D, level->cycles * sizeof *D);
    total[k] = level->y[2 * level->ndof];
    *rhs_evals += level->rhs_evals;
    fricreg_sim_free(level);
    return FRICREG_OK;
}

/* What is left of a window's start in cycle c > x->first of a finer level k: the last change
 * of its difference to level 0, (D_k - D_0)(c) - (D_k - D_0)(c - 1). The motion forgets its
 * start geometrically (the sticking oscillator about 5x a cycle), and for a contraction of at
 * least 2x a cycle the last change bounds what is left. In the window's first cycle there is
 * no change to see yet: the finer levels are still near level 0's motion, not their own (on
 * the sticking oscillator their difference there is a twentieth of the settled one), so its
 * estimate is +infinity. Into delta[levels] (delta[0] = 0). */
static void unsettled(const struct fr_extrap *x, const double D[], size_t c, double delta[])
{
    delta[0] = 0.0;
    for (int k = 1; k < x->levels; k++) {
        const double *Dk = D + (size_t)k * x->cycles;
        delta[k] = (Dk[c] - D[c]) - (Dk[c - 1] - D[c - 1]);
    }
}

/* The extrapolation of column[] and, with a window, its estimate widened by what the
 * unsettled part delta[] of the finer levels moves it. */
static void extrapolate_column(const double column[], const double delta[], int levels, int order,
                               struct fr_richardson *r)
{
    fr_richardson(column, levels, order, r);
    if (delta == NULL)
        return;
    double shifted[FR_RICHARDSON_MAX_LEVELS];
    struct fr_richardson s;
    for (int k = 0; k < levels; k++)
        shifted[k] = column[k] - delta[k];
    fr_richardson(shifted, levels, r->order, &s);
    r->error += fabs(s.value - r->value);
}

/* Extrapolates every cycle of D[levels][cycles] from x->first on and the totals into x. The
 * cycles before a window are level 0's, not extrapolated: estimate +infinity. */
static void combine(struct fr_extrap *x, const double D[], const double total[], int order)
{
    double column[FR_RICHARDSON_MAX_LEVELS], delta[FR_RICHARDSON_MAX_LEVELS];
    double total_unsettled = 0.0;
    struct fr_richardson r;
    for (size_t c = 0; c < x->first; c++) {
        x->D[c] = D[c];
        x->D_err[c] = INFINITY;
    }
    for (size_t c = x->first; c < x->cycles; c++) {
        for (int k = 0; k < x->levels; k++)
            column[k] = D[(size_t)k * x->cycles + c];
        int windowed = x->first > 0, settling = windowed && c > x->first;
        if (settling)
            unsettled(x, D, c, delta);
        extrapolate_column(column, settling ? delta : NULL, x->levels, order, &r);
        x->D[c] = r.value;
        x->D_err[c] = windowed && !settling ? INFINITY : r.error;
        total_unsettled += windowed ? x->D_err[c] : 0.0;
        x->flagged += (size_t)r.flagged;
        x->order = r.order;
        x->observed = r.observed;
    }
    fr_richardson(total, x->levels, order, &x->total);
    x->total.error = fmax(x->total.error, total_unsettled); /* a window: +infinity */
    if (x->cycles == x->first) {
        x->order = x->total.order;
        x->observed = x->total.observed;
    }
}

static int check_arguments(fricreg_sim *sim, double t_end, int levels, int order)
{
    if (sim->running)
        return fr_fail(sim, FRICREG_EINVAL,
                       "run_extrapolated: not allowed during a run (called from the observer)");
    if (!isfinite(t_end))
        return fr_fail(sim, FRICREG_ENONFINITE, "run_extrapolated: t_end is not finite");
    if (levels < 2 || levels > FR_RICHARDSON_MAX_LEVELS)
        return fr_fail(sim, FRICREG_EINVAL, "run_extrapolated: levels = %d must be 2 … %d", levels,
                       FR_RICHARDSON_MAX_LEVELS);
    if (order < 0 || order > FR_RICHARDSON_MAX_ORDER)
        return fr_fail(sim, FRICREG_EINVAL, "run_extrapolated: order = %d must be 0 … %d", order,
                       FR_RICHARDSON_MAX_ORDER);
    return FRICREG_OK;
}

/* The window's first cycle: where the finer levels start, the end of cycle C - window of
 * the C whole cycles in t_end; 0 (from t = 0) when the window covers them all. */
static size_t window_start(const fricreg_sim *sim, double t_end, int window)
{
    double C = fr_whole_cycles(t_end, sim->sys.type->period(&sim->sys));
    return window > 0 && (double)window < C ? (size_t)(C - window) : 0;
}

/* Level 0, with its state at the window's start copied into *start (allocated here). */
static int run_level0(fricreg_sim *sim, double t_end, size_t first, double **start)
{
    *start = NULL;
    if (first > 0) {
        *start = malloc((2 * sim->sys.type->ndof(&sim->sys) + 1) * sizeof **start);
        if (*start == NULL)
            return fr_fail(sim, FRICREG_ENOMEM, "run_extrapolated: out of memory");
    }
    sim->capture_cycle = first;
    sim->capture_y = *start;
    sim->estimate_skip = 1;                   /* the extrapolation is the run's estimate */
    int status = fricreg_sim_run(sim, t_end); /* discards any earlier extrapolation */
    sim->estimate_skip = 0;
    sim->capture_cycle = 0;
    sim->capture_y = NULL;
    return status;
}

static int run_extrapolated(fricreg_sim *sim, double t_end, int levels, int order, int window)
{
    size_t first = window_start(sim, t_end, window);
    double *start = NULL;
    int status = run_level0(sim, t_end, first, &start);
    if (status != FRICREG_OK) {
        free(start);
        return status;
    }
    size_t cycles = sim->cycles;
    if (cycles <= first) /* the observer stopped level 0 before the window's end */
        first = 0;
    struct fr_extrap *x = calloc(1, sizeof *x);
    double *D = malloc(((size_t)levels * cycles + 1) * sizeof *D);
    double total[FR_RICHARDSON_MAX_LEVELS];
    if (x != NULL) {
        x->D = malloc((cycles + 1) * sizeof *x->D);
        x->D_err = malloc((cycles + 1) * sizeof *x->D_err);
    }
    if (x == NULL || D == NULL || x->D == NULL || x->D_err == NULL) {
        fr_extrap_free(x);
        free(D);
        free(start);
        return fr_fail(sim, FRICREG_ENOMEM, "run_extrapolated: out of memory for %zu cycles",
                       cycles);
    }
    x->levels = levels;
    x->cycles = cycles;
    x->first = first;
    x->eps_finest = ldexp(sim->eps, 1 - levels);
    x->rhs_evals = sim->rhs_evals;
    if (cycles > 0)
        memcpy(D, sim->D, cycles * sizeof *D);
    /* Level 0's dissipation over the window (the whole run without one). */
    total[0] = sim->y[2 * sim->ndof] - (first > 0 ? start[2 * sim->ndof] : 0.0);
    /* An observer that stopped level 0 at t = 0 leaves nothing to extrapolate. */
    for (int k = 1; status == FRICREG_OK && k < levels; k++)
        status = sim->t > 0.0 ? run_level(sim, k, sim->t, first, start, D, total, &x->rhs_evals)
                              : (total[k] = 0.0, FRICREG_OK);
    if (status == FRICREG_OK) {
        combine(x, D, total, order);
        sim->extrap = x;
    } else {
        fr_extrap_free(x);
    }
    free(D);
    free(start);
    return status;
}

int fricreg_sim_run_extrapolated(fricreg_sim *sim, double t_end, int levels, int order)
{
    return fricreg_sim_run_extrapolated_window(sim, t_end, levels, order, 0);
}

int fricreg_sim_run_extrapolated_window(fricreg_sim *sim, double t_end, int levels, int order,
                                        int window)
{
    if (sim == NULL)
        return FRICREG_ENULL;
    int status = check_arguments(sim, t_end, levels, order);
    if (status == FRICREG_OK && window < 0)
        status = fr_fail(sim, FRICREG_EINVAL,
                         "run_extrapolated_window: window = %d cycles must be >= 0", window);
    if (status != FRICREG_OK)
        return status;
    status = run_extrapolated(sim, t_end, levels, order, window);
    fr_sim_judge_for_handler(sim); /* the estimate's warnings, after the levels */
    return status;
}

int fricreg_sim_get_extrapolation(const fricreg_sim *sim, int which, double *value)
{
    if (sim == NULL || value == NULL)
        return FRICREG_ENULL;
    const struct fr_extrap *x = sim->extrap;
    if (x == NULL)
        return FRICREG_EINVAL;
    switch (which) {
    case FRICREG_EXTRAP_LEVELS: *value = x->levels; break;
    case FRICREG_EXTRAP_ORDER: *value = x->order; break;
    case FRICREG_EXTRAP_OBSERVED_ORDER: *value = x->observed; break;
    case FRICREG_EXTRAP_FLAGGED_CYCLES: *value = (double)x->flagged; break;
    case FRICREG_EXTRAP_DISSIPATION: *value = x->total.value; break;
    case FRICREG_EXTRAP_DISSIPATION_ERR: *value = x->total.error; break;
    case FRICREG_EXTRAP_EPS_FINEST: *value = x->eps_finest; break;
    case FRICREG_EXTRAP_RHS_EVALS: *value = (double)x->rhs_evals; break;
    default: return FRICREG_EINVAL;
    }
    return FRICREG_OK;
}

int fricreg_sim_get_extrapolated_dissipation(const fricreg_sim *sim, size_t ncycles, double D[],
                                             double err[])
{
    if (sim == NULL || ((D == NULL || err == NULL) && ncycles > 0))
        return FRICREG_ENULL;
    const struct fr_extrap *x = sim->extrap;
    if (x == NULL)
        return FRICREG_EINVAL;
    if (ncycles != x->cycles)
        return FRICREG_ESIZE;
    if (ncycles > 0) {
        memcpy(D, x->D, ncycles * sizeof *D);
        memcpy(err, x->D_err, ncycles * sizeof *err);
    }
    return FRICREG_OK;
}
