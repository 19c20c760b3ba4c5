/* SPDX-License-Identifier: GPL-3.0-or-later */
/* warnings.c — fricreg_sim's checks of plausibility (fricreg_sim_warning_count): the run's
 * settings against the friction law's scale eps (docs/integrators.md, "Warnings"). A warning
 * never changes a result: the checks only read. */
#include <math.h>

#include "sim_internal.h"

/* An adaptive run's velocity tolerance against eps. GSL holds a body velocity to
 * atol_v + rtol |v|, |v| of order 1 in the paper's nondimensional systems, while law (4) reads
 * a contact velocity, a difference of body velocities, within its band |zdot| < eps. Measured
 * on the two blocks at eps = 1e-6 under msbdf (docs/integrators.md, "Absolute tolerances from
 * eps"): a level of 1e-2 eps gave D on cycle 4 1.2e-4 off, 1e-1 eps 3e-3, and
 * atol = rtol = 1e-6 (a level of 2 eps) +8e-3. fricreg's rule from eps holds it to
 * min(1e-3 eps, rtol) and never warns. */
#define TOL_PER_EPS 1e-2

/* The loosest level a velocity is held to, atol_v + rtol x 1 (no relative part under the rule
 * from eps); 0 for a fixed-step run. */
static double velocity_level(const fricreg_sim *sim, double eps)
{
    if (!(sim->rtol > 0.0 || sim->atol > 0.0 || sim->atol_from_eps || sim->atol_vec != NULL))
        return 0.0;
    if (sim->atol_from_eps)
        return fr_sim_rule_atol_v(sim, eps);
    if (sim->atol_vec == NULL)
        return sim->atol + sim->rtol;
    size_t ndof = (sim->atol_n - 1) / 2; /* y = (x, v, D): the velocities' entries */
    double level = 0.0;
    for (size_t i = ndof; i < 2 * ndof; i++)
        level = fmax(level, sim->atol_vec[i] + sim->rtol);
    return level;
}

static void check_tolerances(fricreg_sim *sim)
{
    double eps = 0.0;
    fricreg_sim_get_value(sim, FRICREG_VALUE_EPS, &eps);
    double level = velocity_level(sim, eps);
    if (level > TOL_PER_EPS * eps)
        fr_warn(&sim->warnings, FRICREG_WARN_TOL_LOOSE,
                "the adaptive steps hold a velocity to %.3g (atol + rtol x 1), above 0.01 eps = "
                "%.3g: inside the band |zdot| < eps law (4)'s force is then uncontrolled; take "
                "atol FRICREG_ATOL_FROM_EPS (fricreg-sim: no --atol)",
                level, TOL_PER_EPS * eps);
}

size_t fricreg_sim_warning_count(fricreg_sim *sim)
{
    if (sim == NULL)
        return 0;
    if (sim->running)
        return sim->warnings.n; /* from the observer or the handler: the list as last judged */
    fr_warnings_clear(&sim->warnings);
    check_tolerances(sim);
    fr_sim_check_estimate(sim);
    sim->running = 1; /* the handler may read, not change, the simulation */
    fr_warnings_deliver(&sim->warnings);
    sim->running = 0;
    return sim->warnings.n;
}

int fricreg_sim_set_warning_handler(fricreg_sim *sim, fricreg_warning_handler fn, void *user_data)
{
    if (sim == NULL)
        return FRICREG_ENULL;
    if (sim->running)
        return fr_fail(sim, FRICREG_EINVAL,
                       "set_warning_handler: not allowed during a run "
                       "(called from the observer or the warning handler)");
    fr_warnings_set_handler(&sim->warnings, fn, user_data);
    return FRICREG_OK;
}

void fr_sim_judge_for_handler(fricreg_sim *sim)
{
    if (sim->warnings.handler != NULL)
        fricreg_sim_warning_count(sim);
}

const char *fricreg_sim_warning_message(const fricreg_sim *sim, size_t k)
{
    return sim != NULL ? fr_warnings_message(&sim->warnings, k) : "";
}

int fricreg_sim_get_warning(const fricreg_sim *sim, size_t k, int *code, char *buf, size_t len)
{
    return sim != NULL ? fr_warnings_get(&sim->warnings, k, code, buf, len) : FRICREG_ENULL;
}
