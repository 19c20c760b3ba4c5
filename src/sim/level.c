/* SPDX-License-Identifier: GPL-3.0-or-later */
/* level.c — a companion of a simulation at level k of the ladder eps / 2^k (sim_internal.h,
 * fr_sim_level): every setting copied, eps, a fixed step and an adaptive run's tolerances
 * scaled. The error estimate's companions (error_estimate.c) and the extrapolation's levels
 * (extrapolate.c) are such copies. */
#include <math.h>
#include <stdlib.h>

#include "sim_internal.h"

/* sim_internal.h. Keep this list in step with the settings of struct fricreg_sim. */
int fr_sim_level(const fricreg_sim *sim, int k, double tol_scale, fricreg_sim **out)
{
    fricreg_sim *level = NULL;
    int status = fricreg_sim_create(sim->sys.type->id, &level);
    if (status != FRICREG_OK)
        return status;
    double scale = ldexp(1.0, -k);
    int adaptive = sim->rtol > 0.0 || sim->atol > 0.0 || sim->atol_from_eps || sim->atol_vec;
    level->sys = sim->sys;
    level->law = sim->law;
    level->partition = sim->partition;
    level->unguarded = sim->unguarded;
    level->eps_set = sim->eps * scale;
    level->integrator = sim->integrator;
    level->dt = adaptive ? sim->dt : sim->dt * scale;
    level->rtol = sim->rtol * tol_scale;
    level->atol = sim->atol * tol_scale;
    level->atol_from_eps = sim->atol_from_eps; /* the rule at the level's own eps */
    level->rule_scale = sim->rule_scale * tol_scale;
    if (sim->atol_vec != NULL) {
        level->atol_vec = malloc(sim->atol_n * sizeof *level->atol_vec);
        if (level->atol_vec == NULL) {
            fricreg_sim_free(level);
            return FRICREG_ENOMEM;
        }
        for (size_t i = 0; i < sim->atol_n; i++)
            level->atol_vec[i] = sim->atol_vec[i] * tol_scale;
        level->atol_n = sim->atol_n;
    }
    level->kink_location = sim->kink_location;
    level->max_steps = sim->max_steps; /* the caller's bound holds on every level */
    *out = level;
    return FRICREG_OK;
}
