/* SPDX-License-Identifier: GPL-3.0-or-later */
/* values.c — a structure's scalar results (fricreg_structure_get_value: the time, the energy
 * balance, the error estimate's companions; fricreg_structure_get_stat: the counters). The
 * estimate's values settle auto's screen first, as every read of the estimate does
 * (estimate_companions.c's fr_estimate_settle). */
#include "structure_internal.h"

int fricreg_structure_get_value(const fricreg_structure *s, int which, double *value)
{
    if (s == NULL || value == NULL)
        return FRICREG_ENULL;
    if (which >= FRICREG_SVALUE_COMPANION_CPU && which <= FRICREG_SVALUE_SCREEN_DISS_ERR)
        fr_estimate_settle((fricreg_structure *)s); /* logically const: see estimate_read.c */
    double kinetic = fr_energy_kinetic(s), strain = fr_energy_strain(s);
    const struct fr_energy *e = &s->energy;
    switch (which) {
    case FRICREG_SVALUE_TIME: *value = s->t; break;
    case FRICREG_SVALUE_INPUT: *value = e->input; break;
    case FRICREG_SVALUE_KINETIC: *value = kinetic; break;
    case FRICREG_SVALUE_STRAIN: *value = strain; break;
    case FRICREG_SVALUE_VISCOUS: *value = e->viscous; break;
    case FRICREG_SVALUE_FRICTION: *value = e->friction; break;
    case FRICREG_SVALUE_RESIDUAL:
        *value = e->initial + e->input - kinetic - strain - e->viscous - e->friction - e->jenkins;
        break;
    case FRICREG_SVALUE_INITIAL: *value = e->initial; break;
    case FRICREG_SVALUE_GROUND_PGV: fr_record_peaks(&s->ground, &(double){0}, value); break;
    case FRICREG_SVALUE_JENKINS: *value = e->jenkins; break;
    case FRICREG_SVALUE_COMPANION_CPU: *value = s->companion_cpu; break;
    case FRICREG_SVALUE_COMPANIONS_USED:
        *value = s->estimate_state == FR_ESTIMATE_ACTIVE && !s->fresh ? s->companion_level : -1;
        break;
    case FRICREG_SVALUE_SCREEN_PEAK_ERR: *value = s->screen_peak_err; break;
    case FRICREG_SVALUE_SCREEN_DISS_ERR: *value = s->screen_dissipation_err; break;
    default: return FRICREG_EINVAL;
    }
    return FRICREG_OK;
}

int fricreg_structure_get_stat(const fricreg_structure *s, int which, int64_t *value)
{
    if (s == NULL || value == NULL)
        return FRICREG_ENULL;
    if (which < 0 || which >= FR_NSSTATS)
        return FRICREG_EINVAL;
    *value = s->stats[which];
    return FRICREG_OK;
}
