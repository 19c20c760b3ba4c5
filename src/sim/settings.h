/* SPDX-License-Identifier: GPL-3.0-or-later */
/* settings.h — internal: what a simulation's settings say, read by its run (sim.c,
 * integrate.c), its tolerances (tolerances.c) and its results (results.c); and the discard of
 * a run's state, which a new setting or a new run makes (settings.c). */
#ifndef FRICREG_SIM_SETTINGS_H
#define FRICREG_SIM_SETTINGS_H

#include "sim_internal.h"

/* Frees the working state of the last run and its results (the error estimate's and the
 * extrapolation's too): the getters then report the initial state. The settings stay. */
void fr_sim_free_run(fricreg_sim *sim);

/* Whether a run's steps are adaptive: a tolerance is set (else fixed steps of dt). */
static inline int fr_sim_adaptive(const fricreg_sim *sim)
{
    return sim->rtol > 0.0 || sim->atol > 0.0 || sim->atol_from_eps || sim->atol_vec != NULL;
}

/* The forcing period of the system as set. */
static inline double fr_sim_period(const fricreg_sim *sim)
{
    return sim->sys.type->period(&sim->sys);
}

/* The eps set by fricreg_sim_set_law, or the paper's rule for the current dt. */
static inline double fr_sim_eps_in_use(const fricreg_sim *sim)
{
    return sim->eps_set > 0.0 ? sim->eps_set : sim->sys.type->paper_eps(&sim->sys, sim->dt);
}

#endif
