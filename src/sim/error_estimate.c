/* SPDX-License-Identifier: GPL-3.0-or-later */
/* error_estimate.c — fricreg_sim_set_error_estimate: an a-posteriori estimate of the error of
 * D per cycle against the Coulomb problem (eps -> 0), from companion runs on the extrapolation's
 * ladder (level.c, fr_sim_level): level 1, eps / 2 with, for fixed steps, dt / 2, and for
 * adaptive ones the tolerances / TOL_SCALE; with two companions (the default) level 2 too,
 * eps / 4 and dt / 4 or the tolerances / TOL_SCALE^2.
 *
 * Law (4)'s regularization error in D is c eps^p with p = 1 or 2 (fricreg_sim.h,
 * fricreg_sim_run_extrapolated); along dt / eps fixed a fixed step's error is a function of
 * eps alone and follows it. An adaptive run's tolerance error is not a function of eps: each
 * companion's tolerances are tightened so that its own tolerance error is a fraction of the
 * run's, and the differences then carry the run's. From D, D2, D4 the estimate is
 * base/companion_estimate.c's, fricreg_structure's too: Richardson's correction with the
 * observed order (kind ASYMPTOTIC), or a safe bound where the three show none (kind BOUND);
 * with one companion (1.6's) 3 |D - D2| (kind ASSUMED), calibrated by bench/error_estimate.c
 * (docs/integrators.md, "Error estimate"). FRICREG_WARN_ERROR_ESTIMATE where the headline
 * estimate exceeds the answer tolerance (fricreg_sim_set_answer_rtol), whatever its kind. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "base/companion_estimate.h"
#include "ctx/ctx_driver.h"
#include "settings.h"
#include "sim_internal.h"

#define TOL_SCALE 16.0 /* a companion's tolerances: rtol / 16 a level (rk8pd: ~1.4x the steps) */

int fricreg_sim_set_error_estimate(fricreg_sim *sim, int on)
{
    if (sim == NULL)
        return FRICREG_ENULL;
    if (sim->running)
        return fr_fail(sim, FRICREG_EINVAL,
                       "set_error_estimate: not allowed during a run (called from the observer)");
    if (on != FRICREG_ESTIMATE_OFF && on != FRICREG_ESTIMATE_TWO_COMPANIONS &&
        on != FRICREG_ESTIMATE_ONE_COMPANION)
        return fr_fail(sim, FRICREG_EINVAL,
                       "set_error_estimate: on = %d must be 0, 1 (two companions) or 2 (one)", on);
    sim->error_estimate = on;
    return FRICREG_OK;
}

int fricreg_sim_set_answer_rtol(fricreg_sim *sim, double rtol)
{
    if (sim == NULL)
        return FRICREG_ENULL;
    if (!(rtol > 0.0 && rtol < INFINITY)) /* NaN fails both */
        return fr_fail(sim, FRICREG_EINVAL, "set_answer_rtol: rtol = %g must be finite and > 0",
                       rtol);
    sim->answer_rtol = rtol;
    return FRICREG_OK;
}

static int adaptive(const fricreg_sim *sim)
{
    return sim->rtol > 0.0 || sim->atol > 0.0 || sim->atol_from_eps || sim->atol_vec != NULL;
}

static void estimate_failed(fricreg_sim *sim, const char *msg)
{
    sim->estimate_failed = 1;
    snprintf(sim->estimate_msg, sizeof sim->estimate_msg, "%s", msg);
    for (size_t c = 0; sim->D_err != NULL && c <= sim->cycles; c++) {
        sim->D_err[c] = INFINITY;
        sim->D_kind[c] = FRICREG_EST_KIND_BOUND; /* no estimate: the only safe bound */
    }
    sim->total_err = INFINITY;
}

/* The companion run at level k of the ladder from t = 0 to sim's time into *out (NULL and
 * the estimate failed, with its message, on failure). */
static fricreg_sim *companion_run(fricreg_sim *sim, int k)
{
    fricreg_sim *companion = NULL;
    double tol_scale = adaptive(sim) ? pow(TOL_SCALE, -k) : 1.0;
    if (fr_sim_level(sim, k, tol_scale, &companion) != FRICREG_OK) {
        estimate_failed(sim, "out of memory");
        return NULL;
    }
    companion->start_cycle = sim->start_cycle;
    companion->start_y = sim->start_y;
    int status = fr_sim_run_plain(companion, sim->t);
    if (status == FRICREG_OK && companion->cycles == sim->cycles)
        return companion;
    char msg[sizeof sim->estimate_msg];
    snprintf(msg, sizeof msg, "the companion run at eps = %g failed: %s", companion->eps,
             status == FRICREG_OK ? "it completed another number of cycles"
                                  : fricreg_sim_errmsg(companion));
    estimate_failed(sim, msg);
    fricreg_sim_free(companion);
    return NULL;
}

/* The estimate of q (cycle `cycle`, or the total at sim->cycles) from q2, q4, its kind into
 * D_kind[cycle]. */
static double estimate_of(fricreg_sim *sim, size_t cycle, double q, double q2, double q4)
{
    return fr_companion_estimate(sim->error_estimate, q, q2, q4, &sim->D_kind[cycle]);
}

/* D_err and D_kind for the run's cycles and its total; 0, both NULL, on failure. */
static int allocate_estimate(fricreg_sim *sim)
{
    free(sim->D_err);
    free(sim->D_kind);
    sim->D_err = malloc((sim->cycles + 1) * sizeof *sim->D_err);
    sim->D_kind = malloc((sim->cycles + 1) * sizeof *sim->D_kind);
    if (sim->D_err != NULL && sim->D_kind != NULL)
        return 1;
    free(sim->D_err);
    free(sim->D_kind);
    sim->D_err = NULL;
    sim->D_kind = NULL;
    return 0;
}

void fr_sim_error_estimate(fricreg_sim *sim)
{
    if (!allocate_estimate(sim)) {
        estimate_failed(sim, "out of memory");
        return;
    }
    if (!(sim->t > 0.0)) { /* the observer stopped the run at t = 0: nothing to estimate */
        sim->total_err = 0.0;
        sim->D_kind[0] = FRICREG_EST_KIND_BOUND; /* 0 bounds the nothing done, no order */
        return;
    }
    fricreg_sim *c2 = companion_run(sim, 1), *c4 = c2; /* c4 is ignored with one companion */
    if (c2 != NULL && sim->error_estimate == FRICREG_ESTIMATE_TWO_COMPANIONS)
        c4 = companion_run(sim, 2);
    if (c2 != NULL && c4 != NULL) {
        for (size_t c = 0; c < sim->cycles; c++)
            sim->D_err[c] = estimate_of(sim, c, sim->D[c], c2->D[c], c4->D[c]);
        size_t i = 2 * sim->ndof; /* the total D, the last component of y */
        sim->total_err = estimate_of(sim, sim->cycles, sim->y[i], c2->y[i], c4->y[i]);
    }
    if (c4 != c2)
        fricreg_sim_free(c4);
    fricreg_sim_free(c2);
}

/* GSL's multistep steppers, whose error in D the calibration found not to follow their
 * tolerances (msbdf on the two blocks: ~1e-5 from rtol 1e-3 to 1e-9), though the estimate
 * bounds it: the warning says so when the estimate exceeds what the tolerances ask of D. */
static int multistep(const fricreg_sim *sim)
{
    return adaptive(sim) &&
           (sim->integrator == FRICREG_INT_MSADAMS || sim->integrator == FRICREG_INT_MSBDF);
}

/* The band's work over a time t: the work sum_i mun_i eps t the contacts' bounds do at the band's
 * velocity eps, D's scale for the estimate's round-off floor (fr_estimate_exceeds). On the
 * oscillator stuck under central-imex (x0 = a = 0.5) it is 0.126 a cycle, D about 1e-18 and
 * its estimate 2.5e-18. */
static double band_work(const fricreg_sim *sim, double t)
{
    const double *mun = fr_ctx_bounds(sim->ctx);
    double sum = 0.0;
    for (size_t i = 0; i < sim->m; i++)
        sum += fabs(mun[i]);
    return sum * sim->eps * t;
}

void fr_sim_check_estimate(fricreg_sim *sim)
{
    if (sim->estimate_failed) { /* also when even D_err could not be allocated */
        fr_warn(&sim->warnings, FRICREG_WARN_ERROR_ESTIMATE,
                "no error estimate could be formed (reported as infinite): %s", sim->estimate_msg);
        return;
    }
    if (sim->D_err == NULL)
        return;
    /* The last whole cycle's D, else the total: the headline quantity. */
    size_t c = sim->cycles > 0 ? sim->cycles - 1 : sim->cycles;
    double D = sim->cycles > 0 ? sim->D[c] : sim->y[2 * sim->ndof];
    double err = sim->cycles > 0 ? sim->D_err[c] : sim->total_err;
    double t = sim->cycles > 0 ? fr_sim_period(sim) : sim->t;
    if (fr_estimate_exceeds(err, D, sim->answer_rtol, band_work(sim, t))) {
        char which[48] = "the total dissipation";
        if (sim->cycles > 0)
            snprintf(which, sizeof which, "cycle %zu's dissipation", sim->cycles);
        fr_warn(&sim->warnings, FRICREG_WARN_ERROR_ESTIMATE,
                "the error estimate %.3g of %s %.7g (%s) exceeds twice the answer tolerance "
                "%.3g of it (the estimate bounds the error at about twice its size): halve eps "
                "and dt, or raise --answer-rtol (set_answer_rtol)",
                err, which, D, fr_estimate_kind_name(sim->D_kind[c]), sim->answer_rtol);
    } else if (multistep(sim) && err > fr_sim_dissipation_tolerance(sim, D))
        fr_warn(&sim->warnings, FRICREG_WARN_ERROR_ESTIMATE,
                "the error of msadams and msbdf does not follow their tolerances (the two "
                "blocks: about 1e-5 from rtol 1e-3 to 1e-9): the error estimate of D, %.3g, is "
                "above the %.3g the tolerances ask (atol + rtol |D|, D = %.7g); trust the "
                "estimate, not rtol (it bounded their error in 99%% of the calibration's runs), "
                "or take rk8pd, whose error follows rtol",
                err, fr_sim_dissipation_tolerance(sim, D), D);
}

int fricreg_sim_get_dissipation_error(const fricreg_sim *sim, size_t ncycles, double err[])
{
    if (sim == NULL || (err == NULL && ncycles > 0))
        return FRICREG_ENULL;
    if (sim->D_err == NULL)
        return FRICREG_EINVAL;
    if (ncycles != sim->cycles)
        return FRICREG_ESIZE;
    for (size_t c = 0; c < ncycles; c++)
        err[c] = sim->D_err[c];
    return FRICREG_OK;
}

int fricreg_sim_get_dissipation_error_kind(const fricreg_sim *sim, size_t ncycles, int kind[])
{
    if (sim == NULL || (kind == NULL && ncycles > 0))
        return FRICREG_ENULL;
    if (sim->D_kind == NULL)
        return FRICREG_EINVAL;
    if (ncycles != sim->cycles)
        return FRICREG_ESIZE;
    for (size_t c = 0; c < ncycles; c++)
        kind[c] = sim->D_kind[c];
    return FRICREG_OK;
}
