/* SPDX-License-Identifier: GPL-3.0-or-later */
/* exact.c — fricreg_exact's life cycle and runs: the semi-analytical solution of Eq. (5) under
 * Coulomb friction (1) with force balance at rest (2), its phases found by phases.c into a copy
 * that replaces the solution held only when the run succeeds. Its results: results.c. */
#include <math.h>
#include <stdlib.h>

#include <gsl/gsl_roots.h>

#include "base/error.h"
#include "base/fr_math.h"
#include "closed_form.h"
#include "exact_internal.h"
#include "fricreg_exact.h"
#include "phases.h"
#include "base/free_all.h"

#define MAX_CYCLES 1e6

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
        FR_FREE_ALL(ex->brent, state, ex);
        return FRICREG_ENOMEM;
    }
    *ex->brent = (gsl_root_fsolver){.type = gsl_root_fsolver_brent, .state = state};
    *out = ex;
    return FRICREG_OK;
}

/* Solves into a copy, so that a failed run leaves the solution held as it was. */
static int run_to(fricreg_exact *ex, double t_end)
{
    fricreg_exact work = *ex;
    work.t_end = t_end;
    work.ph = NULL;
    work.n = work.cap = 0;
    for (int k = 0; k < FR_EXACT_STATS; k++)
        work.stats[k] = 0;
    int status = fr_exact_phases(&work, &ex->err);
    if (status != FRICREG_OK) {
        free(work.ph);
        return status;
    }
    free(ex->ph);
    ex->t_end = work.t_end;
    ex->ph = work.ph;
    ex->n = work.n;
    ex->cap = work.cap;
    for (int k = 0; k < FR_EXACT_STATS; k++)
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
                            t_end, t_end / fr_exact_period(ex), fr_exact_period(ex));
    return run_to(ex, t_end);
}

int fricreg_exact_run_cycles(fricreg_exact *ex, int cycles)
{
    if (ex == NULL)
        return FRICREG_ENULL;
    if (cycles < 1 || cycles > MAX_CYCLES)
        return fr_error_set(&ex->err, FRICREG_EINVAL,
                            "run_cycles: cycles = %d must be from 1 to 10^6", cycles);
    return run_to(ex, cycles * fr_exact_period(ex));
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
    FR_FREE_ALL(ex->brent->state, ex->brent, ex->ph, ex);
}

FR_ERROR_GETTERS(fricreg_exact, "NULL exact solution")
