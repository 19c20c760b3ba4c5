/* SPDX-License-Identifier: GPL-3.0-or-later */
/* extrapolate.c — fricreg_sim_run_extrapolated: the same run at eps, eps/2, …, and D
 * extrapolated to eps -> 0 (richardson.h), with its error estimate.
 *
 * Level 0 is the caller's simulation itself; the finer levels are fresh simulations with
 * its settings, so a level never sees another's state. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "richardson.h"
#include "sim_internal.h"

#define sim_fail(sim, ...) fr_error_set(&(sim)->err, __VA_ARGS__)

struct fr_extrap {
    int levels;
    size_t cycles;
    double *D, *D_err; /* [cycles] */
    struct fr_richardson total;
    int order;       /* of the last whole cycle (else of the total) */
    double observed; /* likewise */
    size_t flagged;  /* whole cycles flagged */
    double eps_finest;
    int64_t rhs_evals; /* all levels */
};

void fr_extrap_free(struct fr_extrap *x)
{
    if (x == NULL)
        return;
    free(x->D);
    free(x->D_err);
    free(x);
}

/* A new simulation with every setting of sim, at level k: eps / 2^k, and a fixed step
 * dt / 2^k (an adaptive run keeps its first step and tolerances). Keep this list in step
 * with the settings of struct fricreg_sim. */
static int make_level(const fricreg_sim *sim, int k, fricreg_sim **out)
{
    fricreg_sim *level = NULL;
    int status = fricreg_sim_create(sim->sys.type->id, &level);
    if (status != FRICREG_OK)
        return status;
    double scale = ldexp(1.0, -k);
    int adaptive = sim->rtol > 0.0 || sim->atol > 0.0;
    level->sys = sim->sys;
    level->law = sim->law;
    level->partition = sim->partition;
    level->unguarded = sim->unguarded;
    level->eps_set = sim->eps * scale;
    level->integrator = sim->integrator;
    level->dt = adaptive ? sim->dt : sim->dt * scale;
    level->rtol = sim->rtol;
    level->atol = sim->atol;
    *out = level;
    return FRICREG_OK;
}

/* Runs level k to t_end into D[k * ncycles …] and total[k]; a failure is reported on sim. */
static int run_level(fricreg_sim *sim, int k, double t_end, double D[], double total[],
                     int64_t *rhs_evals)
{
    fricreg_sim *level = NULL;
    int status = make_level(sim, k, &level);
    if (status != FRICREG_OK)
        return sim_fail(sim, status, "run_extrapolated: level %d: out of memory", k);
    status = fricreg_sim_run(level, t_end);
    if (status == FRICREG_OK && level->cycles != sim->cycles)
        status = sim_fail(level, FRICREG_EINTEGRATOR, "completed %zu cycles, level 0 %zu",
                          level->cycles, sim->cycles);
    if (status != FRICREG_OK) {
        sim_fail(sim, status, "run_extrapolated: level %d (eps = %g, dt = %g): %s", k, level->eps,
                 level->dt, fricreg_sim_errmsg(level));
        fricreg_sim_free(level);
        return status;
    }
    if (sim->cycles > 0)
        memcpy(D + (size_t)k * sim->cycles, level->D, sim->cycles * sizeof *D);
    total[k] = level->y[2 * level->ndof];
    *rhs_evals += level->rhs_evals;
    fricreg_sim_free(level);
    return FRICREG_OK;
}

/* Extrapolates every cycle of D[levels][cycles] and the totals into x. */
static void combine(struct fr_extrap *x, const double D[], const double total[], int order)
{
    double column[FR_RICHARDSON_MAX_LEVELS];
    struct fr_richardson r;
    fr_richardson(total, x->levels, order, &x->total);
    x->order = x->total.order;
    x->observed = x->total.observed;
    for (size_t c = 0; c < x->cycles; c++) {
        for (int k = 0; k < x->levels; k++)
            column[k] = D[(size_t)k * x->cycles + c];
        fr_richardson(column, x->levels, order, &r);
        x->D[c] = r.value;
        x->D_err[c] = r.error;
        x->flagged += (size_t)r.flagged;
        x->order = r.order;
        x->observed = r.observed;
    }
}

static int check_arguments(fricreg_sim *sim, double t_end, int levels, int order)
{
    if (sim->running)
        return sim_fail(sim, FRICREG_EINVAL,
                        "run_extrapolated: not allowed during a run (called from the observer)");
    if (!isfinite(t_end))
        return sim_fail(sim, FRICREG_ENONFINITE, "run_extrapolated: t_end is not finite");
    if (levels < 2 || levels > FR_RICHARDSON_MAX_LEVELS)
        return sim_fail(sim, FRICREG_EINVAL, "run_extrapolated: levels = %d must be 2 … %d", levels,
                        FR_RICHARDSON_MAX_LEVELS);
    if (order < 0 || order > FR_RICHARDSON_MAX_ORDER)
        return sim_fail(sim, FRICREG_EINVAL, "run_extrapolated: order = %d must be 0 … %d", order,
                        FR_RICHARDSON_MAX_ORDER);
    return FRICREG_OK;
}

int fricreg_sim_run_extrapolated(fricreg_sim *sim, double t_end, int levels, int order)
{
    if (sim == NULL)
        return FRICREG_ENULL;
    int status = check_arguments(sim, t_end, levels, order);
    if (status == FRICREG_OK)
        status = fricreg_sim_run(sim, t_end); /* level 0; discards any earlier extrapolation */
    if (status != FRICREG_OK)
        return status;
    size_t cycles = sim->cycles;
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
        return sim_fail(sim, FRICREG_ENOMEM, "run_extrapolated: out of memory for %zu cycles",
                        cycles);
    }
    x->levels = levels;
    x->cycles = cycles;
    x->eps_finest = ldexp(sim->eps, 1 - levels);
    x->rhs_evals = sim->rhs_evals;
    if (cycles > 0)
        memcpy(D, sim->D, cycles * sizeof *D);
    total[0] = sim->y[2 * sim->ndof];
    /* An observer that stopped level 0 at t = 0 leaves nothing to extrapolate. */
    for (int k = 1; status == FRICREG_OK && k < levels; k++)
        status = sim->t > 0.0 ? run_level(sim, k, sim->t, D, total, &x->rhs_evals)
                              : (total[k] = 0.0, FRICREG_OK);
    if (status == FRICREG_OK) {
        combine(x, D, total, order);
        sim->extrap = x;
    } else {
        fr_extrap_free(x);
    }
    free(D);
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
