/* SPDX-License-Identifier: GPL-3.0-or-later */
/* results.c — what fricreg_sim reports of its last run: the values (time, eps, period, the
 * dissipation and its error), the counts, the state, the dissipation per cycle, the
 * stick fractions, and the error of the last call. */
#include <string.h>

#include "settings.h"
#include "sim_internal.h"

int fricreg_sim_get_value(const fricreg_sim *sim, int which, double *value)
{
    if (sim == NULL || value == NULL)
        return FRICREG_ENULL;
    switch (which) {
    case FRICREG_VALUE_TIME: *value = sim->t; break;
    case FRICREG_VALUE_EPS: *value = fr_sim_eps_in_use(sim); break;
    case FRICREG_VALUE_DT: *value = sim->dt; break;
    case FRICREG_VALUE_PERIOD: *value = fr_sim_period(sim); break;
    case FRICREG_VALUE_STEPS: *value = (double)sim->steps; break;
    case FRICREG_VALUE_RHS_EVALS: *value = (double)sim->rhs_evals; break;
    case FRICREG_VALUE_CYCLES: *value = (double)sim->cycles; break;
    case FRICREG_VALUE_DISSIPATION: *value = sim->y ? sim->y[2 * sim->ndof] : 0.0; break;
    case FRICREG_VALUE_DISSIPATION_ERROR:
        if (sim->D_err == NULL)
            return FRICREG_EINVAL;
        *value = sim->total_err;
        break;
    case FRICREG_VALUE_DISS_ERROR_KIND:
        if (sim->D_kind == NULL)
            return FRICREG_EINVAL;
        *value = sim->D_kind[sim->cycles];
        break;
    default: return FRICREG_EINVAL;
    }
    return FRICREG_OK;
}

int fricreg_sim_get_stat(const fricreg_sim *sim, int which, int64_t *value)
{
    if (sim == NULL || value == NULL)
        return FRICREG_ENULL;
    switch (which) {
    case FRICREG_SIM_STAT_STEPS: *value = sim->steps; break;
    case FRICREG_SIM_STAT_RHS_EVALS: *value = sim->rhs_evals; break;
    case FRICREG_SIM_STAT_CYCLES: *value = (int64_t)sim->cycles; break;
    case FRICREG_SIM_STAT_REJECTED_STEPS: *value = sim->rejected_steps; break;
    case FRICREG_SIM_STAT_KINKS: *value = sim->kinks; break;
    default: return FRICREG_EINVAL;
    }
    return FRICREG_OK;
}

int fricreg_sim_get_state(const fricreg_sim *sim, size_t ndof, double x[], double v[])
{
    if (sim == NULL || x == NULL || v == NULL)
        return FRICREG_ENULL;
    if (ndof != fricreg_sim_ndof(sim))
        return FRICREG_ESIZE;
    if (sim->y == NULL) /* not run yet: the initial conditions */
        sim->sys.type->initial(&sim->sys, x, v);
    else {
        memcpy(x, sim->y, ndof * sizeof *x);
        memcpy(v, sim->y + ndof, ndof * sizeof *v);
    }
    return FRICREG_OK;
}

int fricreg_sim_get_dissipation(const fricreg_sim *sim, size_t ncycles, double D[])
{
    if (sim == NULL || (D == NULL && ncycles > 0))
        return FRICREG_ENULL;
    if (ncycles != sim->cycles)
        return FRICREG_ESIZE;
    if (ncycles > 0)
        memcpy(D, sim->D, ncycles * sizeof *D);
    return FRICREG_OK;
}

int fricreg_sim_get_stick_fraction(const fricreg_sim *sim, size_t m, double frac[])
{
    if (sim == NULL || frac == NULL)
        return FRICREG_ENULL;
    if (m != fricreg_sim_ncontacts(sim))
        return FRICREG_ESIZE;
    for (size_t i = 0; i < m; i++)
        frac[i] = sim->stick_fraction ? sim->stick_fraction[i] : 0.0;
    return FRICREG_OK;
}

FR_ERROR_GETTERS(fricreg_sim, "NULL simulation")
